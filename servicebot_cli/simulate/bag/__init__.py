"""The ROS 2 bag: messages as CDR, their definitions, and the MCAP file of a rosbag2 directory."""
