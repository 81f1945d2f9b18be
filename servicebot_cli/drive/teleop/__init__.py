"""Keyboard teleoperation: keys to twists, the terminal mode and the status line."""
