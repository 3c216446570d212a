"""Whole models written as a user writes them, each checked against a reference that does
not go through acausal (closed forms, hand-derived equations under scipy, conservation
laws)."""
