"""``python -m fem_racket``: the same as the ``fem-racket`` command."""

import sys

from .cli import main

sys.exit(main())
