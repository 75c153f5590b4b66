"""Figures written whole or not at all, as railjoint writes its files.

A figure is drawn into a hidden temporary beside its name and renamed into
place when complete: a script that fails or is killed half way never leaves a
truncated PNG, and an older figure stays until the new one replaces it. The
temporary's name is railjoint's own (support/temporary_name.h,
".<name>.railjoint-<pid>-0"), so one left by a killed script is removed by the
next railjoint run that writes into that folder.
"""

import os
from pathlib import Path

# Longer names are left out of the temporary's name (255-byte limit on a name).
LONGEST_REPEATED_NAME = 200


def temporary_path(path):
    """The hidden temporary a figure is drawn into before it gets its name."""
    path = Path(path)
    repeated = f".{path.name}." if len(os.fsencode(path.name)) <= LONGEST_REPEATED_NAME else "."
    return path.with_name(f"{repeated}railjoint-{os.getpid()}-0")


def save_figure(fig, path, check=None, **options):
    """fig.savefig(path, **options), whole or not at all; check(), when given,
    runs after the figure is drawn and before it gets its name (it raises to
    keep the figure out)."""
    path = Path(path)
    temporary = temporary_path(path)
    try:
        fig.savefig(temporary, format=options.pop("format", path.suffix[1:] or None), **options)
        if check is not None:
            check()
        os.replace(temporary, path)
    except BaseException:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise
