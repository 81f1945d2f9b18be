// The motor controller's side of the protocol; see controller.h.
#include "controller.h"

namespace servicebot {

namespace {
const uint8_t PAYLOAD[] = {0, 8, 8, 0};  // LEN of PING, SET_WHEELS, SET_ARM, STOP

int16_t clamp(int16_t v, int16_t lo, int16_t hi, bool& limited) {
  if (v < lo || v > hi) limited = true;
  return v < lo ? lo : (v > hi ? hi : v);
}

int8_t slot(uint8_t type) {  // index into PAYLOAD, or -1 for a type we do not take
  switch (type) {
    case PING: return 0;
    case SET_WHEELS: return 1;
    case SET_ARM: return 2;
    case STOP: return 3;
    default: return -1;
  }
}
}  // namespace

Controller::Controller(Hardware& hw, const Limits& limits)
    : counters(), hw_(hw), limits_(limits) {
  last_motion_ms_ = hw_.millis();
}

void Controller::poll() {
  int byte;
  while ((byte = hw_.read_byte()) >= 0) {
    decoder_.feed((uint8_t)byte);
    while (decoder_.next(frame_)) handle(frame_);
  }
  if (moving_ && (uint32_t)(hw_.millis() - last_motion_ms_) >= WATCHDOG_MS) {
    stop_motors();
    watchdog_fired_ = true;
    counters.watchdog_trips++;
  }
}

void Controller::handle(const Frame& in) {
  counters.frames++;
  int8_t kind = slot(in.type);
  if (kind < 0) return nack(in, UNKNOWN_TYPE);
  if (in.len != PAYLOAD[kind]) return nack(in, BAD_LENGTH);
  if (in.type == PING) {
    Frame out = {5, in.seq, VERSION, {PROTOCOL_VERSION, FIRMWARE_MAJOR, FIRMWARE_MINOR}};
    put_i16(out.payload + 3, (int16_t)WATCHDOG_MS);
    return reply(out);
  }
  bool limited = false;
  int16_t values[SLOTS];
  for (uint8_t i = 0; i < SLOTS; i++) values[i] = get_i16(in.payload + 2 * i);
  if (in.type == SET_WHEELS) {
    bool any = false;
    for (uint8_t i = 0; i < SLOTS; i++) {
      values[i] = clamp(values[i], -limits_.wheel_mrad_s, limits_.wheel_mrad_s, limited);
      any = any || values[i] != 0;
    }
    hw_.set_wheels(values);
    moving_ = any;
    last_motion_ms_ = hw_.millis();
    watchdog_fired_ = false;
  } else if (in.type == SET_ARM) {
    for (uint8_t i = 0; i < SLOTS; i++)
      values[i] = clamp(values[i], limits_.arm_lower_mrad, limits_.arm_upper_mrad, limited);
    hw_.set_arm(values);
    moving_ = true;  // the watchdog holds the arm too, as STOP does
  } else {
    stop_motors();
    counters.stops++;
    last_motion_ms_ = hw_.millis();
    watchdog_fired_ = false;
  }
  if (limited) faults_ |= FAULT_LIMIT;
  telemetry(in.seq);
}

void Controller::stop_motors() {
  static const int16_t zero[SLOTS] = {0, 0, 0, 0};
  hw_.set_wheels(zero);
  Measured now;
  hw_.measure(now);
  hw_.set_arm(now.arm_position_mrad);  // the arm holds where it is
  moving_ = false;
}

void Controller::telemetry(uint8_t seq) {
  Measured m;
  hw_.measure(m);
  Frame out = {25, seq, TELEMETRY, {0}};
  for (uint8_t i = 0; i < SLOTS; i++) {
    put_i16(out.payload + 2 * i, (int16_t)(uint16_t)(m.wheel_position_mrad[i] & 0xFFFF));
    put_i16(out.payload + 8 + 2 * i, m.wheel_speed_mrad_s[i]);
    put_i16(out.payload + 16 + 2 * i, m.arm_position_mrad[i]);
  }
  uint8_t faults = faults_ | hw_.faults();
  if (decoder_.crc_errors != crc_reported_) faults |= FAULT_CRC;
  if (watchdog_fired_) faults |= FAULT_WATCHDOG;
  crc_reported_ = decoder_.crc_errors;
  faults_ = 0;
  out.payload[24] = faults;
  reply(out);
}

void Controller::nack(const Frame& in, NackReason reason) {
  counters.nacks++;
  Frame out = {2, in.seq, NACK, {in.type, (uint8_t)reason}};
  reply(out);
}

void Controller::reply(const Frame& out) {
  hw_.write(wire_, encode(out, wire_));
}

}  // namespace servicebot
