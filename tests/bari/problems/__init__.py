"""The DAE problems of the Bari test set, one module each (see ``../testset.py``)."""
