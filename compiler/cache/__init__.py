"""The compile cache: compiled models kept between processes, in a picklable form, found
by the key of their flat model (or of their instance tree) and the compiler's own
fingerprint."""
from .entries import (LoadedCode, enabled, find_by_tree, from_cache, load_notes, lookup,
                      models_dir, portable, store, store_index)
from .keys import fingerprint, flat_key, tree_key

__all__ = ["lookup", "store", "store_index", "find_by_tree", "from_cache", "enabled",
           "models_dir", "portable", "load_notes", "LoadedCode", "flat_key", "tree_key",
           "fingerprint"]
