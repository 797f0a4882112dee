"""Layer L3: instructions for trajectories: templates (default) and a learned speaker."""
