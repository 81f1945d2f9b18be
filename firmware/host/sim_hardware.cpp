// See sim_hardware.h.
#include "sim_hardware.h"

#include <errno.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

namespace servicebot {

double monotonic_s() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}

SimHardware::SimHardware(int fd) : fd_(fd) {
  start_s_ = now_s_ = monotonic_s();
  memset(wheel_rad, 0, sizeof wheel_rad);
  memset(speed, 0, sizeof speed);
  memset(arm_rad, 0, sizeof arm_rad);
  memset(arm_target, 0, sizeof arm_target);
}

uint32_t SimHardware::millis() { return (uint32_t)((monotonic_s() - start_s_) * 1000.0); }

int SimHardware::read_byte() {
  if (in_at_ == in_n_) {
    ssize_t n = read(fd_, in_, sizeof in_);
    if (n <= 0) return -1;
    in_n_ = (int)n;
    in_at_ = 0;
  }
  return in_[in_at_++];
}

void SimHardware::write(const uint8_t* data, uint8_t n) {
  while (n > 0) {
    ssize_t done = ::write(fd_, data, n);
    if (done < 0 && errno != EAGAIN && errno != EINTR) return;  // no reader: dropped
    if (done < 0) continue;
    data += done;
    n -= (uint8_t)done;
  }
}

void SimHardware::advance() {
  double now = monotonic_s(), dt = now - now_s_;
  now_s_ = now;
  for (int i = 0; i < SLOTS; i++) {
    wheel_rad[i] += speed[i] / 1000.0 * dt;
    double target = arm_target[i] / 1000.0, step = 1.0 * dt;
    double gap = target - arm_rad[i];
    arm_rad[i] = (gap > step) ? arm_rad[i] + step : (gap < -step ? arm_rad[i] - step : target);
  }
}

void SimHardware::set_wheels(const int16_t speed_mrad_s[SLOTS]) {
  advance();
  memcpy(speed, speed_mrad_s, sizeof speed);
  bool seen = false;
  for (int c = 0; c < n_commands && !seen; c++)
    seen = memcmp(commands[c], speed, sizeof speed) == 0;
  if (!seen && n_commands < 16) memcpy(commands[n_commands++], speed, sizeof speed);
  for (int i = 0; i < SLOTS; i++) {
    int16_t a = speed[i] < 0 ? (int16_t)-speed[i] : speed[i];
    if (a > max_abs_command) max_abs_command = a;
  }
}

void SimHardware::set_arm(const int16_t target_mrad[SLOTS]) {
  advance();
  memcpy(arm_target, target_mrad, sizeof arm_target);
}

void SimHardware::measure(Measured& out) {
  advance();
  for (int i = 0; i < SLOTS; i++) {
    double mrad = wheel_rad[i] * 1000.0;
    out.wheel_position_mrad[i] = (int32_t)(mrad < 0 ? mrad - 0.5 : mrad + 0.5);
    out.wheel_speed_mrad_s[i] = speed[i];
    double arm = arm_rad[i] * 1000.0;
    out.arm_position_mrad[i] = (int16_t)(arm < 0 ? arm - 0.5 : arm + 0.5);
  }
}

bool SimHardware::moving() const {
  for (int i = 0; i < SLOTS; i++)
    if (speed[i] != 0 || (int16_t)(arm_rad[i] * 1000.0 + (arm_rad[i] < 0 ? -0.5 : 0.5)) != arm_target[i])
      return true;
  return false;
}

}  // namespace servicebot
