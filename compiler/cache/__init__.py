"""The compile cache: picklable compiled models, their entries and their keys."""
