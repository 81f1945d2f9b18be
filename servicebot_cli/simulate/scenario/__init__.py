"""Scenario files: reading them with line numbers, their schema and checks against the robot."""
