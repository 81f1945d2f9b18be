"""Batch mode: rows in from CSV or JSON Lines, results out one per line, streaming."""
