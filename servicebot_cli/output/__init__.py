"""Rendering and writing results; no computation."""
