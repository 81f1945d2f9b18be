"""The controllers, as ros2_control runs them: diff_drive_controller and the arm's trajectory."""
