"""Reusable touch widgets of the operator screens."""
