"""``python -m fem_racket``: the same as the ``fem-racket`` command."""

import sys

from fem_racket.cli import main

sys.exit(main())
