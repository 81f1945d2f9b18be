"""Simulated sensors: LIDAR, IMU, odometry, joint states and camera_info, with their noise."""
