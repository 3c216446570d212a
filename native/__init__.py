"""Native code: building generated C into shared libraries."""
