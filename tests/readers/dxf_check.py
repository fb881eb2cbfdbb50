#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reads a DXF file with ezdxf (Debian's python3-ezdxf) and prints what it read as JSON: the
DXF version, $INSUNITS, the layer table, the entities of model space per layer and type, the
extent of the model-space geometry, and what ezdxf's auditor found.
Exit status: 0 read with no audit error, 1 ezdxf refused the file or its audit found errors,
2 usage.
Usage: python3 tests/readers/dxf_check.py FILE.dxf"""
import json
import sys

import ezdxf
from ezdxf import bbox


def main():
    if len(sys.argv) != 2:
        print("usage: dxf_check.py FILE.dxf", file=sys.stderr)
        return 2
    try:
        doc = ezdxf.readfile(sys.argv[1])
    except (IOError, ezdxf.DXFError) as error:
        print(json.dumps({"read": False, "error": str(error)}))
        return 1
    auditor = doc.audit()
    counts = {}
    for entity in doc.modelspace():
        layer = counts.setdefault(entity.dxf.layer, {})
        layer[entity.dxftype()] = layer.get(entity.dxftype(), 0) + 1
    extent = bbox.extents(doc.modelspace())
    print(json.dumps({
        "read": True,
        "version": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS"),
        "layers": sorted(layer.dxf.name for layer in doc.layers),
        "entities": counts,
        "extent": [list(extent.extmin), list(extent.extmax)] if extent.has_data else None,
        "audit_errors": [str(e.message) for e in auditor.errors],
        "audit_fixes": [str(f.message) for f in auditor.fixes],
    }))
    return 0 if not auditor.has_errors else 1


if __name__ == "__main__":
    sys.exit(main())
