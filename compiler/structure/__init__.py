"""The structural passes, on integers only: the incidence graph, matching and
Dulmage-Mendelsohn, Pantelides, the Sigma-method, state selection, BLT, tearing,
causalization."""
