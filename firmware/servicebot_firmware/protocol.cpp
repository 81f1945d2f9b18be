// Framing and CRC of the servicebot protocol; see protocol.h.
#include "protocol.h"

#include <string.h>

namespace servicebot {

uint16_t crc16(const uint8_t* data, size_t n, uint16_t crc) {
  while (n--) {
    crc ^= (uint16_t)(*data++) << 8;
    for (uint8_t bit = 0; bit < 8; bit++)
      crc = (crc & 0x8000) ? (uint16_t)((crc << 1) ^ 0x1021) : (uint16_t)(crc << 1);
  }
  return crc;
}

void Decoder::drop(uint8_t n) {
  memmove(buf_, buf_ + n, n_ - n);
  n_ -= n;
}

bool Decoder::next(Frame& frame) {
  while (n_ > 0) {
    if (buf_[0] != SYNC1 || (n_ >= 2 && buf_[1] != SYNC2)) {  // garbage before SYNC
      drop(1);
      discarded++;
      continue;
    }
    if (n_ < HEADER_BYTES) return false;
    uint8_t len = buf_[2];
    if (len > MAX_PAYLOAD) {  // not a frame: one byte on, search again
      drop(1);
      crc_errors++;
      continue;
    }
    uint8_t size = HEADER_BYTES + len + 2;
    if (n_ < size) return false;
    uint16_t wire = (uint16_t)(buf_[size - 2] | (buf_[size - 1] << 8));
    if (crc16(buf_ + 2, 3 + len) != wire) {
      drop(1);
      crc_errors++;
      continue;
    }
    frame.len = len;
    frame.seq = buf_[3];
    frame.type = buf_[4];
    memcpy(frame.payload, buf_ + HEADER_BYTES, len);
    drop(size);
    return true;
  }
  return false;
}

void Decoder::feed(uint8_t byte) {
  if (n_ == MAX_FRAME) {  // only when the caller skipped next(); keeps the buffer safe
    drop(1);
    discarded++;
  }
  buf_[n_++] = byte;
}

uint8_t encode(const Frame& frame, uint8_t* out) {
  out[0] = SYNC1;
  out[1] = SYNC2;
  out[2] = frame.len;
  out[3] = frame.seq;
  out[4] = frame.type;
  memcpy(out + HEADER_BYTES, frame.payload, frame.len);
  uint16_t crc = crc16(out + 2, 3 + frame.len);
  out[HEADER_BYTES + frame.len] = (uint8_t)(crc & 0xFF);
  out[HEADER_BYTES + frame.len + 1] = (uint8_t)(crc >> 8);
  return HEADER_BYTES + frame.len + 2;
}

}  // namespace servicebot
