"""``servicebot check``: a catalogue of rules over a robot description, collecting findings.

Light to import: the catalogue and the finding types load no numeric library, so
``--list-rules`` and ``--explain`` answer at once. Rule families import what they need.
"""
