# SPDX-License-Identifier: GPL-3.0-or-later
"""Atomic writes of the batch's files: a temporary file beside the target, flushed to disk, then
renamed over it, so that a reader sees the old file or the new one, never a part.

Cost: one fsync per file written.
"""
import os
import tempfile

_UMASK = os.umask(0o022)  # read by setting it: put back at once
os.umask(_UMASK)


def write_atomically(path, text):
    """Writes `text` (str, UTF-8) to `path`, creating its folder. @raise OSError"""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(path) + ".",
                                         suffix=".tmp")
    try:
        os.fchmod(handle, 0o666 & ~_UMASK)  # as open() would create it, not mkstemp's 0600
        with os.fdopen(handle, "w", encoding="utf-8", newline="") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
