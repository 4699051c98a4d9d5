"""Baselines re-implemented from their published descriptions (SELP, RoboGuard)."""
