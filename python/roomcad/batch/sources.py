# SPDX-License-Identifier: GPL-3.0-or-later
"""The plans of a batch: SOURCE arguments (plans, folders, lists of paths) expanded to one task
per plan, each with the relative path its outputs mirror under --out-dir and its content hash.

Cost: one directory walk per folder and one read of each plan file (the SHA-256 that --resume
compares); no plan is parsed here.
"""
import hashlib
import os
import pathlib

#: What a folder is searched for (recursively), and what a SOURCE argument names as a plan
#: (as does a Sweet Home 3D Home.xml, or NAME.Home.xml, given or listed).
PLAN_SUFFIXES = (".json", ".sh3d", ".ifc")


class BatchError(Exception):
    """A batch that cannot start: a SOURCE that is missing, outputs that would collide, a
    results file that cannot be read. The message names the file and what is wrong."""


def content_hash(path):
    """The SHA-256 (hex) of a regular file's bytes, or "" for one that cannot be read as such
    (missing, a pipe, a device): such a plan is never skipped by --resume."""
    try:
        if not os.path.isfile(path):
            return ""
        with open(path, "rb") as f:
            return hashlib.file_digest(f, "sha256").hexdigest()
    except OSError:
        return ""


def _folder_plans(folder, prefix):
    found = []
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            if name.lower().endswith(PLAN_SUFFIXES):
                path = pathlib.Path(root, name)
                found.append((path, prefix / path.relative_to(folder)))
    return found


def _listed_plans(list_file):
    """The plans of a text file of paths (one a line; blank lines and # comments skipped);
    relative paths are relative to the list's folder and mirrored as written."""
    found = []
    try:
        lines = pathlib.Path(list_file).read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise BatchError(f"{list_file}: cannot read the list of plans: {error}") from None
    for number, line in enumerate(lines, 1):
        entry = line.strip()
        if not entry or entry.startswith("#"):
            continue
        written = pathlib.Path(entry)
        path = written if written.is_absolute() else pathlib.Path(list_file).parent / written
        mirrored = written if not written.is_absolute() and ".." not in written.parts \
            else pathlib.Path(written.name)
        if path.is_dir():
            found += _folder_plans(path, mirrored)
        else:  # a missing listed plan becomes its `refused` row, naming the file
            found.append((path, mirrored))
    return found


def find_plans(sources):
    """Expands SOURCE arguments to [(path, relative path)], in the order given, each plan once.
    @raise BatchError for a SOURCE that does not exist"""
    found = []
    for source in sources:
        path = pathlib.Path(source)
        if path.is_dir():
            found += _folder_plans(path, pathlib.Path())
        elif path.suffix.lower() in PLAN_SUFFIXES or path.name.endswith("Home.xml"):
            if not path.exists():
                raise BatchError(f"{source}: no such plan")
            found.append((path, pathlib.Path(path.name)))
        elif path.is_file():
            found += _listed_plans(path)
        else:
            raise BatchError(f"{source}: no such file or folder (a SOURCE is a plan, a folder "
                             f"of plans, or a text file listing them)")
    seen, unique = set(), []
    for path, mirrored in found:
        key = os.path.abspath(path)
        if key not in seen:
            seen.add(key)
            unique.append((path, mirrored))
    return unique


def check_outputs_apart(plans, out_dir):
    """@raise BatchError when two plans would write the same files under out_dir."""
    if out_dir is None:
        return
    owner = {}
    for path, mirrored in plans:
        key = mirrored.with_suffix("")
        if key in owner:
            raise BatchError(f"{owner[key]} and {path} would both write "
                             f"{pathlib.Path(out_dir) / key}.*: give their folders as SOURCE, "
                             f"so that the outputs mirror them")
        owner[key] = path
