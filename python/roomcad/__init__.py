# SPDX-License-Identifier: GPL-3.0-or-later
"""roomcad: room plans validated exactly, built as exact solids, rendered and drawn.

The same library as the ``roomcad`` command: ``Plan.load(path).validate().to_dict()`` is what
``roomcad validate --format json`` prints, ``plan.build().save("x.obj")`` writes the bytes of
``roomcad build -o x.obj``, and ``plan.render()`` the pixels of ``roomcad render``. Every
failure raises :class:`roomcad.Error` with a ``.code`` of the project's error vocabulary.
"""
from ._roomcad import Error, Finding, Model, Plan, Report, import_ifc, import_sweethome3d, sun

__all__ = ["Error", "Finding", "Model", "Plan", "Report", "import_ifc", "import_sweethome3d",
           "sun"]
