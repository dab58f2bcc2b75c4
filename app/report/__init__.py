"""Core results as the typed output models: the one path from validated inputs
through the core to a response, and the formula behind each reported number."""
