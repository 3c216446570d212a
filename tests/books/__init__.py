"""Tests of the seed books' systems that run in acausal (INVENTORY section 1 rows)."""
