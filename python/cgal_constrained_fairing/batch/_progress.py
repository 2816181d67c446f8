"""The batch's progress bar on stderr: files done out of all."""

import importlib.util
import sys
from pathlib import Path
from typing import Optional

from ._report_file import Row


def show_progress(progress: Optional[bool]) -> bool:
    """`progress`, or by default whether stderr is a terminal and tqdm is installed."""
    if progress is None:
        return sys.stderr.isatty() and importlib.util.find_spec("tqdm") is not None
    if not isinstance(progress, bool):
        raise ValueError(f"progress must be None, True or False (got {progress!r})")
    return progress


class Bar:
    """A tqdm bar of files on stderr, or a line rewritten in place without tqdm."""

    def __init__(self, total: int, done: int):
        self._total, self._done = total, done
        try:
            from tqdm import tqdm
        except ImportError:
            self._bar = None
            self._line()
        else:
            self._bar = tqdm(total=total, initial=done, desc="fairing files", unit="file",
                             file=sys.stderr)

    def update(self, row: Row):
        self._done += 1
        if self._bar is not None:
            self._bar.set_postfix_str(f"{Path(row['path']).name}: {row['status']}",
                                      refresh=False)
            self._bar.update(1)
        else:
            self._line()

    def close(self):
        if self._bar is not None:
            self._bar.close()
        else:
            sys.stderr.write("\n")
            sys.stderr.flush()

    def _line(self):
        sys.stderr.write(f"\rfairing files: {self._done}/{self._total}\x1b[K")
        sys.stderr.flush()
