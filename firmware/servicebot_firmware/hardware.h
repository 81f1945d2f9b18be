// What the controller needs of the board: time, the UART, the motors and the encoders.
// servicebot_firmware.ino implements it for an Arduino Uno; firmware/host/ for a pty.
#pragma once
#include <stdint.h>

#include "protocol.h"

namespace servicebot {

struct Measured {
  int32_t wheel_position_mrad[SLOTS];  // continuous; the wire carries it modulo 2^16
  int16_t wheel_speed_mrad_s[SLOTS];
  int16_t arm_position_mrad[SLOTS];
};

class Hardware {
 public:
  virtual uint32_t millis() = 0;
  virtual int read_byte() = 0;  // -1 when nothing arrived
  virtual void write(const uint8_t* data, uint8_t n) = 0;
  // Run each wheel at this joint velocity until told otherwise [mrad/s].
  virtual void set_wheels(const int16_t speed_mrad_s[SLOTS]) = 0;
  // Move each arm joint to this target at its velocity limit, and hold it [mrad].
  virtual void set_arm(const int16_t target_mrad[SLOTS]) = 0;
  virtual void measure(Measured& out) = 0;
  virtual uint8_t faults() = 0;  // FAULT_MOTOR and FAULT_ESTOP as the board sees them
};

}  // namespace servicebot
