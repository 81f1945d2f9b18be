// The firmware's hardware on a Linux host: a pseudo-terminal for the UART, the clock for
// millis(), and motors that turn exactly as commanded (encoders integrate the speeds, the
// arm moves at 1 rad/s). Tests drive this build with `servicebot drive`.
#pragma once
#include <stdint.h>

#include "../servicebot_firmware/hardware.h"

namespace servicebot {

class SimHardware : public Hardware {
 public:
  explicit SimHardware(int fd);
  uint32_t millis() override;
  int read_byte() override;
  void write(const uint8_t* data, uint8_t n) override;
  void set_wheels(const int16_t speed_mrad_s[SLOTS]) override;
  void set_arm(const int16_t target_mrad[SLOTS]) override;
  void measure(Measured& out) override;
  uint8_t faults() override { return 0; }

  void advance();            // integrate up to now
  bool moving() const;
  double wheel_rad[SLOTS];   // continuous wheel angles [rad]
  int16_t speed[SLOTS];      // commanded [mrad/s]
  double arm_rad[SLOTS];
  int16_t arm_target[SLOTS];
  int16_t commands[16][SLOTS];  // distinct wheel commands, first 16
  int n_commands = 0;
  int16_t max_abs_command = 0;

 private:
  int fd_;
  double start_s_;
  double now_s_;
  uint8_t in_[256];
  int in_n_ = 0, in_at_ = 0;
};

double monotonic_s();

}  // namespace servicebot
