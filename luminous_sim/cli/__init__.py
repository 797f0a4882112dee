"""The `luminous` command: thin shells over tested library functions."""
