"""Atomic file output: a temporary file beside the target, renamed into place, so a failure
never leaves a partial file behind (as the CLI's ``write_atomic``)."""

from __future__ import annotations

import os
import tempfile
from typing import Union


def write_atomic(path: Union[str, "os.PathLike[str]"], data: bytes) -> None:
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".", dir=directory)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
