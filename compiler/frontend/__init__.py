"""The language to the flat model: flattening, units, discrete and sampled values,
delays, alias elimination."""
