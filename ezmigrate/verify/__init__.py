"""Verification: load legacy and migrated versions in child processes and compare models."""
