#!/usr/bin/env python3
"""integrations/blender/make_zip.py: the add-on as a zip Blender installs.

    python3 integrations/blender/make_zip.py OUT.zip

Writes OUT.zip with the folder scaf_uv/ at its top (the layout
Preferences > Add-ons > Install... expects), the .py files only, in a
fixed order with fixed timestamps (the same bytes every time). The CMake
target `blender_addon` writes build/scaf_uv.zip with it.
"""

import os
import sys
import zipfile


def main():
    if len(sys.argv) != 2:
        sys.stderr.write("usage: make_zip.py OUT.zip\n")
        return 2
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scaf_uv")
    names = sorted(n for n in os.listdir(src) if n.endswith(".py"))
    tmp = sys.argv[1] + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for n in names:
            info = zipfile.ZipInfo("scaf_uv/" + n, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = 0o644 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            with open(os.path.join(src, n), "rb") as f:
                z.writestr(info, f.read())
    os.replace(tmp, sys.argv[1])  # never a partial zip under the final name
    return 0


if __name__ == "__main__":
    sys.exit(main())
