"""The bottom layer every package may import: errors, reading input, writing files, JSON."""
