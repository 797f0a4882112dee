"""Layer L3: symbolic planning, navigation and the oracle that turns tasks into trajectories."""
