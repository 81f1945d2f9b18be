"""One drive run on an open port: the command loop, signals, the stop and the telemetry log."""
