// The motor controller's side of the protocol: one reply per valid frame, limits,
// the 500 ms watchdog and the fault flags. Board-independent (see hardware.h).
#pragma once
#include "hardware.h"
#include "protocol.h"

namespace servicebot {

struct Limits {
  int16_t wheel_mrad_s;  // the URDF's wheel velocity limit
  int16_t arm_lower_mrad;
  int16_t arm_upper_mrad;
};

struct Counters {
  uint16_t frames;
  uint16_t stops;
  uint16_t nacks;
  uint16_t watchdog_trips;
};

class Controller {
 public:
  static const uint16_t WATCHDOG_MS = 500;
  static const uint8_t FIRMWARE_MAJOR = 1;
  static const uint8_t FIRMWARE_MINOR = 0;

  Controller(Hardware& hw, const Limits& limits);
  // Read what arrived, answer it, and run the watchdog; call as often as possible.
  void poll();
  const Decoder& decoder() const { return decoder_; }
  Counters counters;

 private:
  void handle(const Frame& in);
  void reply(const Frame& out);
  void telemetry(uint8_t seq);
  void stop_motors();
  void nack(const Frame& in, NackReason reason);

  Hardware& hw_;
  Limits limits_;
  Decoder decoder_;
  Frame frame_;
  uint8_t wire_[MAX_FRAME];
  uint8_t faults_ = FAULT_RESET;
  uint16_t crc_reported_ = 0;
  uint32_t last_motion_ms_ = 0;
  bool moving_ = false;
  bool watchdog_fired_ = false;
};

}  // namespace servicebot
