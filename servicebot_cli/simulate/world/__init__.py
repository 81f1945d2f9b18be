"""The world: its solids and meshes, rays against them, and planar motion stopped by them."""
