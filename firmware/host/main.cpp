// The servicebot firmware on a Linux host: serves the controller on a pseudo-terminal.
//
// Prints the device path on stdout's first line; runs until SIGTERM, SIGINT or SIGHUP, then
// prints one JSON line with what the motors did and exits 0. With a state file argument it
// also rewrites that JSON there (atomically) ten times a second, for tests that watch it.
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include "../servicebot_firmware/controller.h"
#include "sim_hardware.h"

using servicebot::Controller;
using servicebot::SimHardware;

static volatile sig_atomic_t stop_requested = 0;
static void on_signal(int) { stop_requested = 1; }

static void state_json(FILE* out, const Controller& c, const SimHardware& hw, double clock) {
  fprintf(out, "{\"clock_s\": %.6f, \"moving\": %s, \"wheels_rad\": [", clock,
          hw.moving() ? "true" : "false");
  for (int i = 0; i < servicebot::SLOTS; i++) fprintf(out, "%s%.6f", i ? ", " : "", hw.wheel_rad[i]);
  fprintf(out, "], \"arm_rad\": [");
  for (int i = 0; i < servicebot::SLOTS; i++) fprintf(out, "%s%.6f", i ? ", " : "", hw.arm_rad[i]);
  fprintf(out, "], \"wheel_commands_mrad_s\": [");
  for (int k = 0; k < hw.n_commands; k++) {
    fprintf(out, "%s[%d, %d, %d, %d]", k ? ", " : "", hw.commands[k][0], hw.commands[k][1],
            hw.commands[k][2], hw.commands[k][3]);
  }
  fprintf(out,
          "], \"max_abs_wheel_command_mrad_s\": %d, \"frames\": %u, \"stops\": %u, "
          "\"nacks\": %u, \"watchdog_trips\": %u, \"crc_errors\": %u}\n",
          hw.max_abs_command, c.counters.frames, c.counters.stops, c.counters.nacks,
          c.counters.watchdog_trips, c.decoder().crc_errors);
}

static void write_state(const char* path, const Controller& c, const SimHardware& hw) {
  char tmp[4096];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  FILE* f = fopen(tmp, "w");
  if (!f) return;
  state_json(f, c, hw, servicebot::monotonic_s());
  fclose(f);
  rename(tmp, path);
}

int main(int argc, char** argv) {
  int master, slave;
  if (openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    perror("openpty");
    return 1;
  }
  termios raw;
  tcgetattr(slave, &raw);
  cfmakeraw(&raw);
  tcsetattr(slave, TCSANOW, &raw);
  fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
  struct sigaction action = {};
  action.sa_handler = on_signal;
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGHUP, &action, nullptr);
  printf("%s\n", ttyname(slave));
  fflush(stdout);

  SimHardware hw(master);
  servicebot::Limits limits = {500, -1570, 1570};  // the real robot's URDF
  Controller controller(hw, limits);
  const char* state_path = argc > 1 ? argv[1] : nullptr;
  double next_state = 0;
  while (!stop_requested) {
    pollfd fds = {master, POLLIN, 0};
    poll(&fds, 1, 2);
    controller.poll();
    if (state_path && servicebot::monotonic_s() >= next_state) {
      write_state(state_path, controller, hw);
      next_state = servicebot::monotonic_s() + 0.1;
    }
  }
  hw.advance();
  if (state_path) write_state(state_path, controller, hw);
  state_json(stdout, controller, hw, servicebot::monotonic_s());
  return 0;
}
