#!/usr/bin/env python3
"""The fenced blocks of a language in a README, run as written (python: each block; js: the
first) or written to a file (--extract: the first, for compiled languages): the bindings' README
examples are tested this way.

    run_block.py python README.md            # runs every ```python block with this interpreter
    run_block.py js README.md [NODE]          # writes it next to the package and runs node on it
    run_block.py --extract csharp README.md OUT.cs
"""
import os
import re
import subprocess
import sys


def blocks(language, readme):
    text = open(readme, encoding="utf-8").read()
    found = re.findall(r"^```" + re.escape(language) + r"\n(.*?)^```", text, re.S | re.M)
    if not found:
        sys.exit("no ```%s block in %s" % (language, readme))
    return found


def block(language, readme):
    return blocks(language, readme)[0]


def main(argv):
    if argv[0] == "--extract":
        language, readme, out = argv[1:4]
        with open(out, "w", encoding="utf-8") as f:
            f.write(block(language, readme))
        return 0
    language, readme = argv[0], argv[1]
    if language == "python":
        for i, code in enumerate(blocks(language, readme)):
            exec(compile(code, "%s (```python block %d)" % (readme, i + 1), "exec"),
                 {"__name__": "__main__"})
        return 0
    code = block(language, readme)
    if language == "js":
        node, package = argv[2], argv[3]
        path = os.path.join(package, "readme_example.mjs")
        with open(path, "w", encoding="utf-8") as f:
            f.write(code)
        return subprocess.call([node, path])
    sys.exit("unknown language " + language)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
