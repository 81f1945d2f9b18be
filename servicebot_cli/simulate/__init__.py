"""``servicebot simulate``: the headless kinematic simulator.

Sub-packages: ``scenario`` (what a run does), ``controllers`` (base and arm), ``sensors``,
``world`` (solids, rays, motion), ``bag`` (the ROS 2 bag) and ``files`` (CSV, plot, window).
"""
