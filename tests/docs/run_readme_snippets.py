#!/usr/bin/env python3
"""tests/docs/run_readme_snippets: README.md and docs/*.md run as written.

The ctest docs/readme_snippets. A newcomer copies the commands of the
README and of the pages in docs/ into a terminal in a fresh clone; this
test does the same:

  1. Every fenced code block of README.md and docs/*.md is tagged: ```sh (run), ```c or
     ```python with file=NAME (written to NAME, which a ```sh block must
     compile or run), or ```text (synopses, trees: not code). A block may
     opt out of running with `skip=REASON` after the language (REASON says
     why, e.g. it installs Debian packages as root); any other block is an
     error. The scripts a skipped block runs (`bash scripts/X.sh`) must
     still exist, be executable and pass `bash -n`.
  2. The files git would clone (tracked + untracked-not-ignored) are copied
     into a temporary folder, with `build` a link to the build tree ctest
     just built. The ```sh blocks run there in one bash (set -euo
     pipefail, so state like `export` carries over as in one terminal),
     with HOME a temporary folder: README.md's first, then each page of
     docs/ in name order, each page's in its order. A page must not need
     files another page makes (each starts with the `scaf gen` lines it
     needs), so a reader can start on any page. Building again would take
     minutes, so a `cmake` on PATH turns `cmake -S . -B build` and `cmake
     --build build` into checks that `build` is that tree, and passes
     everything else (`cmake --install build ...`) to the real cmake.
     With a sanitizer build (SANITIZER_CFLAGS given), `cc` adds those flags
     and `python3` preloads the sanitizer runtime (python/tests/
     sanitizer_env.sh), as the install test does.
  3. Every relative link of README.md and docs/*.md ([text](path)) names a
     file of the repository, no text points outside it (`../...`), and
     every `path` in backquotes that starts with a top-level folder of the
     repository (src/, docs/, tests/, ...) and ends in / or an extension
     exists.

usage: run_readme_snippets.py SOURCE_DIR BUILD_DIR [SANITIZER_CFLAGS]
Exit 0 pass, 1 fail, 77 skip (sanitizer build whose runtime cannot be
preloaded into python).
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

LANGS = {"sh", "c", "python", "text"}
RUNNABLE = {"sh"}


def fail(msg):
    print("FAIL: " + msg)
    return 1


def parse_blocks(path):
    """[(line, lang, attrs, text)] of the fenced blocks of a Markdown file;
    attrs: {"file": NAME, "skip": REASON} as given."""
    blocks, cur = [], None
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if cur is None:
                m = re.match(r"^```(.*)$", line.rstrip("\n"))
                if m:
                    info = m.group(1).strip()
                    lang, _, rest = info.partition(" ")
                    attrs = {}
                    skip = re.search(r"\bskip=(.*)$", rest)
                    if skip:
                        attrs["skip"] = skip.group(1).strip()
                        rest = rest[: skip.start()]
                    fm = re.search(r"\bfile=(\S+)", rest)
                    if fm:
                        attrs["file"] = fm.group(1)
                    cur = (n, lang, attrs, [])
            elif line.startswith("```"):
                blocks.append((cur[0], cur[1], cur[2], "".join(cur[3])))
                cur = None
            else:
                cur[3].append(line)
    if cur is not None:
        blocks.append((cur[0], "unterminated", {}, ""))
    return blocks


def check_blocks(doc, blocks, src):
    errors = []
    runnable_text = "".join(t for _, lang, a, t in blocks if lang in RUNNABLE and "skip" not in a)
    for line, lang, attrs, text in blocks:
        where = "%s:%d" % (doc, line)
        if lang not in LANGS:
            errors.append("%s: a code block tagged %r: tag it sh (runs), c/python with file=NAME, "
                          "or text (not code)" % (where, lang))
            continue
        if "skip" in attrs and not attrs["skip"]:
            errors.append("%s: skip= needs a reason" % where)
        if lang in ("c", "python") and "file" not in attrs and "skip" not in attrs:
            errors.append("%s: a %s block needs file=NAME (and a sh block that uses NAME) or skip=REASON"
                          % (where, lang))
        if "file" in attrs and not re.search(r"(^|[\s/])" + re.escape(attrs["file"]) + r"\b", runnable_text):
            errors.append("%s: file=%s is not used by any sh block that runs" % (where, attrs["file"]))
        if lang == "sh" and "skip" in attrs:
            for script in re.findall(r"\b(scripts/[\w.-]+\.sh)\b", text):
                p = os.path.join(src, script)
                if not os.path.isfile(p):
                    errors.append("%s: %s does not exist" % (where, script))
                    continue
                if not os.access(p, os.X_OK):
                    errors.append("%s: %s is not executable" % (where, script))
                r = subprocess.run(["bash", "-n", p], capture_output=True, text=True)
                if r.returncode != 0:
                    errors.append("%s: bash -n %s: %s" % (where, script, r.stderr.strip()))
    return errors


def repo_files(src):
    """Relative paths of what a clone has: tracked and untracked files that
    .gitignore does not exclude (so a new, not yet committed file counts)."""
    try:
        r = subprocess.run(["git", "-C", src, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                           capture_output=True, check=True)
        files = [f for f in r.stdout.decode().split("\0") if f]
        return [f for f in files if os.path.isfile(os.path.join(src, f))]
    except (OSError, subprocess.CalledProcessError):
        out = []
        for root, dirs, names in os.walk(src):
            rel = os.path.relpath(root, src)
            dirs[:] = [d for d in dirs if not (rel == "." and (d.startswith("build") or d in (".git", "out")))
                       and d != "__pycache__"]
            out += [os.path.normpath(os.path.join(rel, n)) for n in names]
        return out


def check_links(src, files):
    errors = []
    top = {f.split("/")[0] for f in files if "/" in f}
    paths = set(files)
    for f in files:
        while "/" in f:
            f = os.path.dirname(f)
            paths.add(f)
    docs = ["README.md"] + sorted(f for f in files if f.startswith("docs/") and f.endswith(".md"))
    for doc in docs:
        with open(os.path.join(src, doc), encoding="utf-8") as f:
            text = f.read()
        here = os.path.dirname(doc)
        for m in re.finditer(r"\[[^\]]*\]\(([^)\s]+)\)", text):
            target = m.group(1)
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue
            rel = os.path.normpath(os.path.join(here, target.split("#")[0]))
            line = text.count("\n", 0, m.start()) + 1
            if rel.startswith("..") or rel not in paths:
                errors.append("%s:%d: link to %s: no such file in the repository" % (doc, line, target))
        for m in re.finditer(r"`([^`\s]+)`", text):
            token = m.group(1)
            line = text.count("\n", 0, m.start()) + 1
            if token.startswith("../"):
                errors.append("%s:%d: `%s` points outside the repository" % (doc, line, token))
                continue
            first = token.split("/")[0]
            # a path: a top-level folder first, and a folder (ends in /) or a
            # file with an extension (`python/test_python` is a ctest name)
            if ("/" in token and first in top and re.search(r"(/|\.\w+)$", token)
                    and not re.search(r"[<>*{}$]", token)):
                rel = os.path.normpath(token.rstrip("/"))
                if rel not in paths:
                    errors.append("%s:%d: `%s` does not exist in the repository" % (doc, line, token))
    return errors


CMAKE_SHIM = r"""#!/usr/bin/env bash
# README snippet test: the tree is already built (see run_readme_snippets.py).
build="$SNIPPET_BUILD_DIR"
same() { [ "$(cd "$1" 2>/dev/null && pwd -P)" = "$(cd "$build" && pwd -P)" ]; }
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  case "${args[i]}" in
    --install) exec "$SNIPPET_REAL_CMAKE" "$@" ;;
    --build)
      same "${args[i+1]}" || { echo "cmake shim: --build ${args[i+1]} is not the tested build tree" >&2; exit 1; }
      echo "(README test: ${args[i+1]} is already built)"; exit 0 ;;
    -B)
      same "${args[i+1]}" || { echo "cmake shim: -B ${args[i+1]} is not the tested build tree" >&2; exit 1; }
      echo "(README test: ${args[i+1]} is already configured)"; exit 0 ;;
  esac
done
exec "$SNIPPET_REAL_CMAKE" "$@"
"""


def write_shim(folder, name, text):
    p = os.path.join(folder, name)
    with open(p, "w") as f:
        f.write(text)
    os.chmod(p, 0o755)


def sanitizer_env(src, lib):
    """Environment additions for python on an instrumented library, {} for
    a plain one, None when it cannot run (skip)."""
    script = 'source "%s"; scaf_python_sanitizer_env "%s" || exit 77; ' \
             'printf "%%s\\0%%s" "${LD_PRELOAD:-}" "${ASAN_OPTIONS:-}"' % (
                 os.path.join(src, "python", "tests", "sanitizer_env.sh"), lib)
    r = subprocess.run(["bash", "-c", script], capture_output=True)
    if r.returncode == 77:
        return None
    preload, asan = r.stdout.decode().split("\0")
    return {"LD_PRELOAD": preload, "ASAN_OPTIONS": asan} if preload else {}


def run_snippets(src, build, docs, files, cflags):
    """docs: [(name, blocks)] in the order they run."""
    real_cmake = shutil.which("cmake")
    tmp_root = os.path.join(build, "test-tmp")
    os.makedirs(tmp_root, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="readme.", dir=tmp_root)
    try:
        repo = os.path.join(tmp, "repo")
        for f in files:
            os.makedirs(os.path.dirname(os.path.join(repo, f)), exist_ok=True)
            shutil.copy2(os.path.join(src, f), os.path.join(repo, f))
        os.symlink(os.path.abspath(build), os.path.join(repo, "build"))
        shims = os.path.join(tmp, "shims")
        os.makedirs(shims)
        os.makedirs(os.path.join(tmp, "home"))
        write_shim(shims, "cmake", CMAKE_SHIM)
        env = dict(os.environ)
        for k in ("SCAF_LIBRARY", "PYTHONPATH", "PKG_CONFIG_PATH", "LD_LIBRARY_PATH"):
            env.pop(k, None)
        env.update(HOME=os.path.join(tmp, "home"), PATH=shims + os.pathsep + env.get("PATH", ""),
                   SNIPPET_BUILD_DIR=os.path.abspath(build), SNIPPET_REAL_CMAKE=real_cmake,
                   OPENBLAS_NUM_THREADS="1", PYTHONDONTWRITEBYTECODE="1")
        if cflags:
            cc = shutil.which("cc")
            write_shim(shims, "cc", '#!/bin/sh\nexec "%s" "$@" %s\n' % (cc, cflags))
            extra = sanitizer_env(src, os.path.join(build, "libscaf.so"))
            if extra is None:
                print("sanitizer runtime cannot be preloaded into python: skipped")
                return 77
            if extra:
                py = shutil.which("python3")
                write_shim(shims, "python3", '#!/bin/sh\nLD_PRELOAD="%s" ASAN_OPTIONS="%s" exec "%s" "$@"\n'
                           % (extra["LD_PRELOAD"], extra["ASAN_OPTIONS"], py))
        script = []
        for doc, blocks in docs:
            for line, lang, attrs, text in blocks:
                if "file" in attrs and "skip" not in attrs:
                    with open(os.path.join(repo, attrs["file"]), "w") as f:
                        f.write(text)
                if lang in RUNNABLE and "skip" not in attrs:
                    script.append('echo "### %s:%d"\n%s\n' % (doc, line, text))
        with open(os.path.join(tmp, "readme.sh"), "w") as f:
            f.write("set -euo pipefail\n" + "".join(script))
        r = subprocess.run(["bash", os.path.join(tmp, "readme.sh")], cwd=repo, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=500)
        print(r.stdout[-6000:])
        if r.returncode != 0:
            last = re.findall(r"### (\S+\.md:\d+)", r.stdout)
            return fail("the block at %s exited with status %d" % (last[-1] if last else "?", r.returncode))
        every = [b for _, blocks in docs for b in blocks]
        print("README.md and %d pages of docs/: %d sh blocks ran, %d files written, %d blocks skipped"
              " with a reason" % (len(docs) - 1, len(script), sum("file" in a for _, _, a, _ in every),
                                  sum("skip" in a for _, _, a, _ in every)))
        return 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    src, build = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    cflags = argv[3] if len(argv) > 3 else ""
    files = repo_files(src)
    names = ["README.md"] + sorted(f for f in files if f.startswith("docs/") and f.endswith(".md"))
    docs = [(name, parse_blocks(os.path.join(src, name))) for name in names]
    errors = check_links(src, files)
    for name, blocks in docs:
        errors += check_blocks(name, blocks, src)
    for e in errors:
        print("FAIL: " + e)
    if errors:
        return 1
    return run_snippets(src, build, docs, files, cflags)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
