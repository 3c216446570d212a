"""``python -m acausal``: the command line (:mod:`acausal.cli`)."""
from .cli import main

raise SystemExit(main())
