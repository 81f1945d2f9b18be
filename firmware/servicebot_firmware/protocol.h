// The servicebot serial protocol v1 (docs/serial-protocol.md): frames, CRC and messages.
// Pure C++ with fixed-size buffers: no heap, no Arduino headers, so the host builds it too.
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace servicebot {

const uint8_t SYNC1 = 0xAA;
const uint8_t SYNC2 = 0x55;
const uint8_t MAX_PAYLOAD = 32;
const uint8_t HEADER_BYTES = 5;  // SYNC1 SYNC2 LEN SEQ TYPE
const uint8_t MAX_FRAME = HEADER_BYTES + MAX_PAYLOAD + 2;
const uint8_t PROTOCOL_VERSION = 1;
const uint8_t SLOTS = 4;  // wheels, and arm joints

enum MsgType : uint8_t {
  PING = 0x01, SET_WHEELS = 0x10, SET_ARM = 0x11, STOP = 0x12,
  VERSION = 0x81, TELEMETRY = 0x90, NACK = 0xFF,
};
enum NackReason : uint8_t { UNKNOWN_TYPE = 1, BAD_LENGTH = 2 };
enum Fault : uint8_t {
  FAULT_WATCHDOG = 0x01, FAULT_CRC = 0x02, FAULT_LIMIT = 0x04, FAULT_MOTOR = 0x08,
  FAULT_ESTOP = 0x10, FAULT_RESET = 0x20,
};

// CRC-16/CCITT-FALSE: polynomial 0x1021, initial 0xFFFF, not reflected, no final XOR.
uint16_t crc16(const uint8_t* data, size_t n, uint16_t crc = 0xFFFF);

struct Frame {
  uint8_t len;
  uint8_t seq;
  uint8_t type;
  uint8_t payload[MAX_PAYLOAD];
};

// Bytes in, whole frames out, resynchronising after garbage as the document says: find
// SYNC, reject LEN > 32 or a bad CRC by dropping one byte and searching again.
class Decoder {
 public:
  // Add one received byte.
  void feed(uint8_t byte);
  // The next valid frame, if the bytes so far hold one (call until false).
  bool next(Frame& frame);
  uint16_t crc_errors = 0;  // candidates dropped for a bad CRC or LEN
  uint16_t discarded = 0;   // bytes dropped while searching for SYNC

 private:
  void drop(uint8_t n);
  uint8_t buf_[MAX_FRAME];
  uint8_t n_ = 0;
};

// A whole frame on the wire for `frame`; returns its length (7 + LEN).
uint8_t encode(const Frame& frame, uint8_t* out);

inline int16_t get_i16(const uint8_t* p) { return (int16_t)(p[0] | (p[1] << 8)); }
inline void put_i16(uint8_t* p, int16_t v) {
  p[0] = (uint8_t)(v & 0xFF);
  p[1] = (uint8_t)(((uint16_t)v) >> 8);
}

}  // namespace servicebot
