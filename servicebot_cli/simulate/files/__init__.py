"""What a run leaves for people: CSV files, the plot, the live window and the progress bar."""
