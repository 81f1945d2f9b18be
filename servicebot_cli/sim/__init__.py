"""The headless kinematic simulator behind ``servicebot simulate``."""
