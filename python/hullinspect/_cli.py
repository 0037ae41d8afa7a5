"""The `hullinspect` command a pip install puts on PATH: runs the CLI built with this package."""

import os
import sys
from pathlib import Path


def main():
    cli = Path(__file__).resolve().parent / "bin" / "hullinspect"
    if not cli.is_file():
        sys.stderr.write(f"hullinspect: {cli}: not found (this copy of the package was not built "
                         "by pip; use the CLI of the CMake build)\n")
        return 1
    os.execv(cli, [str(cli), *sys.argv[1:]])


if __name__ == "__main__":
    sys.exit(main())
