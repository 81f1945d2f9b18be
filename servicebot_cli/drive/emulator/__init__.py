"""The motor controller emulated: firmware state machines, the wire model and a pseudo-terminal."""
