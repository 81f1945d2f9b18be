"""Sweeps: one scenario over seeds, a grid of values and random draws, with expectations."""
