"""Entry point of scenewright's CAD worker (see scenewright_cad/worker.py).

Started by the Rust runner as `python -I -B cad_worker.py --root DIR`; `-I` keeps the
environment and the user's site-packages out, so the package is found next to this file.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from scenewright_cad.worker import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
