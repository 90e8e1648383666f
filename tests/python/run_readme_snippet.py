#!/usr/bin/python3
"""Runs the README's h5py snippet (its first ```python block) verbatim.

The snippet opens "r.h5"; this script runs it in the folder of the results file
given, after copying that file to r.h5 there. Usage: run_readme_snippet.py README.md RESULTS.h5
"""
import os
import re
import shutil
import sys


def main(readme, results):
    text = open(readme, encoding="utf-8").read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    if not blocks:
        print("README has no ```python block")
        return 1
    folder = os.path.dirname(os.path.abspath(results))
    if os.path.basename(results) != "r.h5":
        shutil.copyfile(results, os.path.join(folder, "r.h5"))
    os.chdir(folder)
    exec(compile(blocks[0], "README.md snippet", "exec"), {})
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
