"""Robot descriptions: files in, one shared model out."""
