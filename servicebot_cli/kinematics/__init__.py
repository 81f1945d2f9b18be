"""Pure kinematics over joint values and Pinocchio models."""
