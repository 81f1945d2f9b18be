// servicebot motor controller for an Arduino Uno (ATmega328P): the servicebot serial
// protocol v1 (docs/serial-protocol.md) over the USB UART at 9600 baud, 8N1.
//
// Board-specific code lives in UnoHardware below, behind the small Hardware interface
// (hardware.h); controller.cpp and protocol.cpp are the same on every board and on the
// host build of firmware/host/ that the tests drive. Wiring assumed here (change the pin
// table for your board):
//   - four DC motors on two dual H-bridges (L298N-style): one PWM pin and one direction
//     pin per wheel, in the URDF's wheel order (front left, front right, rear left, rear
//     right);
//   - one encoder channel per wheel on a pin-change interrupt (A0..A3), counted in the
//     direction of the command (single-channel encoders);
//   - no arm servos: the arm joints report a 1 rad/s ramp towards their targets, which is
//     where servo or smart-actuator code goes.
#include <Arduino.h>

#include "controller.h"

namespace {

using servicebot::Measured;
using servicebot::SLOTS;

const uint8_t PWM_PIN[SLOTS] = {5, 6, 9, 10};
const uint8_t DIR_PIN[SLOTS] = {4, 7, 8, 12};
const uint8_t ENCODER_PIN[SLOTS] = {A0, A1, A2, A3};
const int16_t WHEEL_LIMIT_MRAD_S = 500;  // the URDF's wheel velocity limit
const int32_t ENCODER_TICKS_PER_REV = 3436;
const int16_t ARM_MRAD_PER_MS = 1;  // 1 rad/s, the URDF's arm velocity limit

volatile int32_t ticks[SLOTS];
volatile int8_t tick_sign[SLOTS];
volatile uint8_t last_pins;

// Counts a tick on every edge of each encoder channel, in the commanded direction.
ISR(PCINT1_vect) {
  uint8_t pins = PINC & 0x0F;
  uint8_t changed = pins ^ last_pins;
  last_pins = pins;
  for (uint8_t i = 0; i < SLOTS; i++)
    if (changed & (1 << i)) ticks[i] += tick_sign[i];
}

class UnoHardware : public servicebot::Hardware {
 public:
  void begin() {
    Serial.begin(9600);
    for (uint8_t i = 0; i < SLOTS; i++) {
      pinMode(PWM_PIN[i], OUTPUT);
      pinMode(DIR_PIN[i], OUTPUT);
      pinMode(ENCODER_PIN[i], INPUT_PULLUP);
      analogWrite(PWM_PIN[i], 0);
    }
    last_pins = PINC & 0x0F;
    PCMSK1 = 0x0F;        // A0..A3
    PCICR |= _BV(PCIE1);  // pin-change interrupts on port C
    last_ms_ = millis();
  }

  uint32_t millis() override { return ::millis(); }
  int read_byte() override { return Serial.read(); }
  void write(const uint8_t* data, uint8_t n) override { Serial.write(data, n); }

  void set_wheels(const int16_t speed_mrad_s[SLOTS]) override {
    for (uint8_t i = 0; i < SLOTS; i++) {
      int16_t v = speed_mrad_s[i];
      speed_[i] = v;
      tick_sign[i] = v < 0 ? -1 : 1;
      digitalWrite(DIR_PIN[i], v < 0 ? HIGH : LOW);
      int32_t magnitude = v < 0 ? -(int32_t)v : v;
      analogWrite(PWM_PIN[i], (uint8_t)(magnitude * 255 / WHEEL_LIMIT_MRAD_S));
    }
  }

  void set_arm(const int16_t target_mrad[SLOTS]) override {
    ramp_arm();
    for (uint8_t i = 0; i < SLOTS; i++) arm_target_[i] = target_mrad[i];
  }

  void measure(Measured& out) override {
    ramp_arm();
    for (uint8_t i = 0; i < SLOTS; i++) {
      noInterrupts();
      int32_t count = ticks[i];
      interrupts();
      // mrad = ticks * 2 pi * 1000 / ticks_per_rev, in integers: 6283 / 3436 per tick
      out.wheel_position_mrad[i] = count * 6283L / ENCODER_TICKS_PER_REV;
      out.wheel_speed_mrad_s[i] = speed_[i];  // open loop: the commanded speed
      out.arm_position_mrad[i] = arm_[i];
    }
  }

  uint8_t faults() override { return 0; }  // no current sense or e-stop input wired

 private:
  void ramp_arm() {
    uint32_t now = ::millis();
    int32_t step = (int32_t)(now - last_ms_) * ARM_MRAD_PER_MS;
    last_ms_ = now;
    for (uint8_t i = 0; i < SLOTS; i++) {
      int32_t gap = (int32_t)arm_target_[i] - arm_[i];
      arm_[i] = gap > step ? arm_[i] + step : (gap < -step ? arm_[i] - step : arm_target_[i]);
    }
  }

  int16_t speed_[SLOTS] = {0, 0, 0, 0};
  int16_t arm_[SLOTS] = {0, 0, 0, 0};
  int16_t arm_target_[SLOTS] = {0, 0, 0, 0};
  uint32_t last_ms_ = 0;
};

UnoHardware hardware;
const servicebot::Limits limits = {WHEEL_LIMIT_MRAD_S, -1570, 1570};
servicebot::Controller* controller = nullptr;

}  // namespace

void setup() {
  hardware.begin();
  static servicebot::Controller instance(hardware, limits);
  controller = &instance;
}

void loop() { controller->poll(); }
