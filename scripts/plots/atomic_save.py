"""Figures written whole or not at all, as railjoint writes its files.

A figure is drawn into a hidden temporary beside its name and renamed into
place when complete: a script that fails or is killed half way never leaves a
truncated PNG, and an older figure stays until the new one replaces it. The
temporary's name is railjoint's own (scenes/report/temporary_name.h,
".<name>.railjoint-<pid>-0"), so one left by a killed script is removed by the
next railjoint run that writes into that folder.
"""

import os
from pathlib import Path

# Longer names are left out of the temporary's name (255-byte limit on a name).
LONGEST_REPEATED_NAME = 200


def save_figure(fig, path, **options):
    path = Path(path)
    repeated = f".{path.name}." if len(os.fsencode(path.name)) <= LONGEST_REPEATED_NAME else "."
    temporary = path.with_name(f"{repeated}railjoint-{os.getpid()}-0")
    try:
        fig.savefig(temporary, format=path.suffix[1:] or None, **options)
        os.replace(temporary, path)
    except BaseException:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise
