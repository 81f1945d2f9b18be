"""The two serial protocols, host side: servicebot binary frames and ROSArduinoBridge text."""
