"""The examples' --output-dir: the folder made where needed, and a path that cannot be one (a file
of that name, a path through one, no permission) refused as a usage error, not a traceback."""

import pathlib


def output_dir(parser, given):
    """The folder `given` (--output-dir) as a pathlib.Path, made if it does not exist; else
    parser.error (exit status 2) naming it and why."""
    out = pathlib.Path(given)
    if out.exists() and not out.is_dir():
        parser.error(f"--output-dir {out}: not a directory")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        parser.error(f"--output-dir {out}: cannot make the directory: {error.strerror}")
    return out
