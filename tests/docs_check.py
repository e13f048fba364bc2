#!/usr/bin/python3
"""Checks the documentation against the repository (CTest docs_layout_and_commands; standard library only).

1. Layout tables: every table under a "Layout" heading of README.md or docs/*.md names only files and folders
   that exist. Checked are the first column's entries and, in the other columns, every `code` token that is a
   path (has a '/' or a file extension; globs allowed) and every relative link. A token is looked up from the
   repository's top folder, from the folder the table lists (the `folder/` named in the line above the table),
   from the row's own folder and, for a bare file name, anywhere under the row's folder. Bare words (module and
   target names such as `rigid` or `fv_anim_frames`) are not paths and are not checked.
2. Every top-level folder of the repository (git ls-files) is a first-column entry `folder/` of a layout table,
   and every file directly in a folder whose table lists it (scripts/, docs/*.md) is an entry of that table.
3. Every command shown in a fenced block of README.md and docs/*.md is run or listed here as not run, with the
   reason: `$ frictionviz ...` examples with their output are compared by readme_examples.sh (CTest
   readme_examples, cli_doc_examples: the files given with --compared); the other commands are looked up in
   RUN and NOT_RUN below. A command that is in neither fails the test, and so does an entry that no longer
   matches any command. The RUN commands of one block run in order, through bash with `frictionviz` on the PATH,
   in a scratch folder that links the repository's top-level entries (so tests/data/... reads as for a user in
   the top folder, and outputs land in the scratch folder): each must exit 0, and write its --out path.

Usage: docs_check.py --repo DIR --frictionviz EXE [--compared FILE.md ..]
"""

import argparse
import concurrent.futures
import fnmatch
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

# Commands run by this test (file, command as shown, without its trailing comment).
RUN = [
    ("README.md", "mkdir -p out"),
    ("README.md", "frictionviz render --figure fig10,fig14 --out out/"),
    ("README.md", "frictionviz animate --zeta 0.3 --theta 60 --rdisp 2 --i 1 --out loop.gif"),
    ("README.md", "frictionviz fit --data tests/data/synthetic_theta90_rdisp3_i0.csv"),
    ("docs/cli.md", "mkdir -p out"),
    ("docs/cli.md", "frictionviz render --figure fig10,fig14 --out out/"),
    ("docs/cli.md", "frictionviz render --figure map --rdisp 5 --i 0 --format png,pdf --out out/"),
    ("docs/cli.md", "frictionviz render --figure map --rdisp 1,10 --model dahl,rigid --out out/"),
    ("docs/cli.md", "frictionviz render --figure fig19 --data tests/data/synthetic_two_angles_rdisp2_i0.csv "
                    "--amplitude 0.7 --out out/"),
    ("docs/cli.md", "frictionviz render --figure rx --theta 30,60 --rdisp 1,10 --i 0.5 --zeta 0.02:2 --size 640x400 "
                    "--out out/"),
    ("docs/cli.md", "frictionviz render --spec out/rx.json --format pdf --out out/"),
    ("docs/cli.md", "frictionviz render --lesson 3 --format png,pdf --out out/"),
    ("docs/cli.md", "frictionviz render --lesson 5 --format pdf --page a4 --caption --out out/"),
    ("docs/teaching.md", "frictionviz animate --lesson 2 --out along.gif"),
    ("docs/teaching.md", "frictionviz animate --lesson 3 --view compare --out compare.gif"),
    ("docs/teaching.md", "frictionviz animate --lesson 3 --out across.gif"),
    ("docs/teaching.md", "mkdir -p handout"),
    ("docs/teaching.md", "frictionviz render --lesson 5 --format png,pdf --page a4 --caption --out handout/"),
    ("docs/cli.md", "frictionviz render --figure fig4 --theta 0 --zeta 0.5 --format pdf --page a4 --caption "
                    "--out out/"),
    ("docs/cli.md", "frictionviz render --figure fig5 --format pdf,svg --page column --caption --out out/"),
    ("docs/cli.md", "frictionviz animate --zeta 0.3 --theta 60 --rdisp 2 --i 1 --out loop.gif"),
    ("docs/cli.md", "frictionviz animate --zeta 0.15 --theta 90 --rdisp 2 --i 0 --view scene --size 1920x1200 "
                    "--scale 2 --out loop.mp4"),
]

# Commands not run here, and why (file, command or "re:" and a regular expression matching whole commands,
# reason).
NOT_RUN = [
    ("README.md", "./scripts/run.sh",
     "the main job: apt-get installs packages and builds the app; this test runs inside such a build"),
    ("README.md", "./scripts/test.sh", "the test suite this test belongs to (CI runs it: .ci/run)"),
    ("README.md", "./scripts/build-web.sh && ./scripts/serve-web.sh",
     "build-web.sh is run by the web_build test (label web); serve-web.sh serves until Ctrl-C"),
    ("docs/cli.md", r"re:frictionviz .*(\[|\|| [A-Z]+( |$)).*",
     "the synopsis: placeholders (Z, DEG, FILE) and alternatives, not a command"),
    ("docs/development.md", "./scripts/setup.sh [GROUP..]",
     "apt-get installs packages (as root); every build script runs it"),
    ("docs/development.md", "./scripts/build.sh", "test.sh runs it (the build this test runs in)"),
    ("docs/development.md", "./scripts/build.sh app", "run.sh runs it (the build this test runs in, app only)"),
    ("docs/development.md", "./scripts/run.sh",
     "the main job: installs, builds, opens a window (or renders into screenshots/, rewriting them)"),
    ("docs/development.md", "./scripts/build-web.sh", "run by the web_build test (label web)"),
    ("docs/development.md", "./scripts/test.sh", "the test suite this test belongs to (CI runs it)"),
    ("docs/development.md", "./scripts/check-format.sh",
     "CI runs it first (.ci/run); it may apt-get install clang-format"),
    ("docs/development.md", "re:ctest --test-dir build .*",
     "runs tests of this suite from build/, which the scripts make (here the tree may be elsewhere)"),
    ("docs/development.md", "./scripts/test-sanitize.sh",
     "CI runs it (.ci/run): an instrumented build and run of the suite, tens of minutes on 2 cores"),
    ("docs/development.md", "./scripts/fuzz.sh [SECONDS]",
     "CI runs fuzz.sh 20 (.ci/run); SECONDS is a placeholder"),
    ("docs/library.md", "./scripts/build.sh app", "run.sh runs it (the build this test runs in, app only)"),
    ("docs/library.md", "cmake --install build --prefix ~/.local",
     "install_consumer (label install) installs the build into a prefix of its own and builds tests/consumer "
     "against it"),
    ("docs/figures.md", "FV_UPDATE_SNAPSHOTS=1 ctest --test-dir build -R Snapshot",
     "rewrites the snapshot baselines in tests/snapshots/"),
    ("docs/web.md", "./scripts/build-web.sh [OUTDIR]",
     "run by the web_build test (label web); OUTDIR is a placeholder"),
    ("docs/teaching.md", "./scripts/build-web.sh && ./scripts/serve-web.sh --lan",
     "build-web.sh is run by the web_build test (label web); serve-web.sh serves until Ctrl-C"),
    ("docs/teaching.md", "frictionviz gui --link-base http://192.168.1.20:8000/ --lesson 1",
     "opens the app's window (gui_* tests run it headless; a --link-base is checked by fv_gui_tests)"),
    ("docs/web.md", "./scripts/serve-web.sh [--lan] [SITE_DIR] [PORT]",
     "a web server that runs until Ctrl-C"),
]

SHELL_INFO = {"sh", "bash", "shell", "console"}
PATH_TOKEN = re.compile(r"^[\w.*?-]+(/[\w.*?-]*)*/?$")
FILE_EXT = re.compile(r"\.[A-Za-z][A-Za-z0-9]*$")

failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


def doc_files(repo):
    return ["README.md"] + sorted(os.path.relpath(p, repo) for p in glob.glob(os.path.join(repo, "docs", "*.md")))


# ---------------------------------------------------------------------------------------------------- layout


def layout_tables(text):
    """Yields (heading line number, folder named above the table or '', rows) for the tables in Layout sections."""
    lines = text.split("\n")
    in_layout, level, in_fence = False, 0, False
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("```"):
            in_fence = not in_fence
        m = None if in_fence else re.match(r"^(#+)\s+(.*)$", line)
        if m:
            if in_layout and len(m.group(1)) <= level:
                in_layout = False
            if re.fullmatch(r"(repository )?layout\b.*", m.group(2), re.I) and not in_layout:
                in_layout, level = True, len(m.group(1))
        if in_layout and line.startswith("|"):
            start = i
            above = next((lines[k] for k in range(i - 1, -1, -1) if lines[k].strip()), "")
            folder = ""
            fm = re.search(r"`([\w.-]+/)`", above) if not above.startswith("|") else None
            if fm:
                folder = fm.group(1)
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                rows.append((i + 1, lines[i]))
                i += 1
            yield start + 1, folder, rows[2:]  # header and separator left out
            continue
        i += 1


def split_row(row):
    # Cells are separated by '|' outside `code` (a code token may hold a '|').
    cells, cur, in_code = [], "", False
    for ch in row.strip().strip("|"):
        if ch == "`":
            in_code = not in_code
        if ch == "|" and not in_code:
            cells.append(cur.strip())
            cur = ""
        else:
            cur += ch
    cells.append(cur.strip())
    return cells


def exists(repo, doc_dir, token, table_folder, row_folder):
    if token.startswith("/"):
        return False
    bases = [repo, os.path.join(repo, table_folder), os.path.join(repo, row_folder), os.path.join(repo, doc_dir)]
    for base in bases:
        if glob.glob(os.path.join(base, token.rstrip("/"))):
            return True
    if "/" not in token.rstrip("/"):
        # A bare file name: under the row's folder, else anywhere (`bench-web.sh` in the bench/ row).
        for folder in ([row_folder] if row_folder else []) + [""]:
            for _root, dirs, files in os.walk(os.path.join(repo, folder)):
                if any(fnmatch.fnmatch(name, token.rstrip("/")) for name in files + dirs):
                    return True
    return False


def generated(repo, token):
    """True for paths the scripts make and git ignores (build/, build-web/site): outputs, not sources."""
    if shutil.which("git") and os.path.exists(os.path.join(repo, ".git")):
        return subprocess.run(["git", "-C", repo, "check-ignore", "-q", "--no-index", token]).returncode == 0
    return token.startswith("build")


def check_layout(repo, tracked):
    entries = {}  # table folder -> set of first-column entries
    tables = checked = 0
    for doc in doc_files(repo):
        doc_dir = os.path.dirname(doc)
        text = open(os.path.join(repo, doc), encoding="utf-8").read()
        for line_no, folder, rows in layout_tables(text):
            tables += 1
            names = entries.setdefault(folder, set())
            for row_line, row in rows:
                cells = split_row(row)
                first = cells[0]
                link = re.match(r"^\[[^\]]*\]\(([^)#]+)(#[^)]*)?\)$", first)
                code = re.match(r"^`([^`]+)`$", first)
                if link:
                    entry = os.path.normpath(os.path.join(doc_dir, link.group(1)))
                    if not os.path.exists(os.path.join(repo, entry)):
                        fail(f"{doc}:{row_line}: layout entry {first} names {entry}, which does not exist")
                    names.add(os.path.relpath(entry, folder) if folder else entry)
                    checked += 1
                    row_folder = os.path.dirname(entry)
                elif code:
                    entry = code.group(1)
                    if not exists(repo, doc_dir, entry, folder, ""):
                        fail(f"{doc}:{row_line}: layout entry `{entry}` does not exist"
                             f"{' in ' + folder if folder else ''}")
                    names.add(entry)
                    checked += 1
                    row_folder = os.path.join(folder, entry) if entry.endswith("/") else folder
                else:
                    fail(f"{doc}:{row_line}: layout row without a `path` or a link in its first column: {first}")
                    continue
                rest = " | ".join(cells[1:])
                for token in re.findall(r"`([^`]+)`", rest):
                    if " " in token or "::" in token or not PATH_TOKEN.match(token):
                        continue
                    if "/" not in token and not FILE_EXT.search(token):
                        continue  # a bare word: a module, target or label name
                    checked += 1
                    if not exists(repo, doc_dir, token, folder, row_folder) and not generated(repo, token):
                        fail(f"{doc}:{row_line}: `{token}` (row {first}) does not exist")
                for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", rest):
                    if re.match(r"^[a-z]+:", target):
                        continue
                    checked += 1
                    if not os.path.exists(os.path.join(repo, doc_dir, target)):
                        fail(f"{doc}:{row_line}: link {target} (row {first}) does not exist")
    if tables == 0:
        fail("no layout table found under a 'Layout' heading in README.md or docs/*.md")
    top_level = sorted({p.split("/")[0] for p in tracked if "/" in p})
    named = entries.get("", set())
    for folder in top_level:
        if folder + "/" not in named:
            fail(f"top-level folder {folder}/ is not named in a layout table")
    for folder, names in entries.items():
        if not folder:
            continue
        for p in tracked:
            if p.startswith(folder) and "/" not in p[len(folder):]:
                name = p[len(folder):]
                if folder == "docs/" and not name.endswith(".md"):
                    continue
                if name not in names:
                    fail(f"{p} is not named in the layout table of {folder}")
    print(f"layout: {tables} tables, {checked} paths; top-level folders {', '.join(top_level)} all checked")


# ---------------------------------------------------------------------------------------------------- commands


def strip_comment(line):
    # A trailing "# comment" after whitespace, outside quotes.
    quote = None
    for k, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (k == 0 or line[k - 1].isspace()):
            return line[:k].rstrip()
    return line.rstrip()


def doc_commands(repo):
    """Yields (file, line, block, command, compared) for every command in the fenced blocks of the docs; block is
    the line of the block's opening fence."""
    for doc in doc_files(repo):
        in_fence, info, block = False, "", 0
        for n, line in enumerate(open(os.path.join(repo, doc), encoding="utf-8").read().split("\n"), 1):
            if line.startswith("```"):
                in_fence, info, block = (not in_fence), line[3:].strip().lower(), n
                continue
            if not in_fence:
                continue
            if line.startswith("$ "):
                yield doc, n, block, line[2:].strip(), True
            elif info in SHELL_INFO:
                command = strip_comment(line)
                if command:
                    yield doc, n, block, command, False
            elif line.startswith("frictionviz "):
                yield doc, n, block, strip_comment(line), False


def matches(pattern, command):
    if pattern.startswith("re:"):
        return re.fullmatch(pattern[3:], command) is not None
    return pattern == command


def run_block(repo, exe, commands):
    """Runs one block's commands in order in a scratch folder; returns (command, error) for the first failure."""
    linked = [name for name in os.listdir(repo) if name != ".git"]
    with tempfile.TemporaryDirectory(prefix="fv-docs-") as work:
        for name in linked:
            os.symlink(os.path.join(repo, name), os.path.join(work, name))
        bin_dir = os.path.join(work, ".bin")
        os.mkdir(bin_dir)
        os.symlink(exe, os.path.join(bin_dir, "frictionviz"))
        env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
        env["PATH"] = bin_dir + os.pathsep + env.get("PATH", "/usr/bin:/bin")
        for command in commands:
            argv = shlex.split(command)
            out = argv[argv.index("--out") + 1] if "--out" in argv[:-1] else None
            if out and os.path.normpath(out).split("/")[0] in linked:
                return command, "its --out is inside the repository: give it a path of its own (out/, loop.gif)"
            try:
                proc = subprocess.run(["bash", "-c", command], cwd=work, env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, timeout=120)
            except subprocess.TimeoutExpired:
                return command, "timed out after 120 s"
            if proc.returncode != 0:
                return command, f"exit {proc.returncode}: {proc.stdout.decode(errors='replace')[-1500:]}"
            if out:
                path = os.path.join(work, out)
                if not os.path.exists(path) or (os.path.isdir(path) and not os.listdir(path)):
                    return command, f"exit 0 but nothing written to {out}"
    return None


def check_commands(repo, exe, compared):
    used_run, used_skip = set(), set()
    blocks = {}  # (file, block line) -> RUN commands in their order
    counts = {"compared": 0, "run": 0, "not run": 0}
    for doc, line, block, command, is_example in doc_commands(repo):
        if is_example:
            if doc in compared and command.startswith("frictionviz "):
                counts["compared"] += 1
            else:
                fail(f"{doc}:{line}: example `$ {command}` with output is not compared by readme_examples.sh (add "
                     "a readme_examples.sh test of the file in tests/CMakeLists.txt and pass it with --compared)")
            continue
        run = [k for k, (f, c) in enumerate(RUN) if f == doc and c == command]
        skip = [k for k, (f, c, _why) in enumerate(NOT_RUN) if f == doc and matches(c, command)]
        if run:
            used_run.update(run)
            blocks.setdefault((doc, block), []).append(command)
            counts["run"] += 1
        elif skip:
            used_skip.update(skip)
            counts["not run"] += 1
        else:
            fail(f"{doc}:{line}: command `{command}` is neither run nor listed as not run: add it to RUN or "
                 "NOT_RUN (with the reason) in tests/docs_check.py")
    for k, (doc, command) in enumerate(RUN):
        if k not in used_run:
            fail(f"RUN lists `{command}` for {doc}, which no longer shows it")
    for k, (doc, command, _why) in enumerate(NOT_RUN):
        if k not in used_skip:
            fail(f"NOT_RUN lists `{command}` for {doc}, which no longer shows it")
    # A frictionviz command shown twice (README.md and docs/cli.md) runs once: a later block needs only its own
    # setup (mkdir), not another's outputs. Two blocks at a time (the machine has two cores).
    seen = set()
    for key, commands in blocks.items():
        blocks[key] = [c for c in commands if not (c.startswith("frictionviz ") and c in seen)]
        seen.update(commands)
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = {key: pool.submit(run_block, repo, exe, commands) for key, commands in blocks.items()}
        for (doc, block), future in results.items():
            error = future.result()
            if error:
                fail(f"{doc}: block at line {block}: `{error[0]}`: {error[1]}")
    print(f"commands: {counts['compared']} examples compared by readme_examples, {counts['run']} run here "
          f"({len(blocks)} blocks), {counts['not run']} listed as not run")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repo", required=True)
    parser.add_argument("--frictionviz", required=True)
    parser.add_argument("--compared", action="append", default=[])
    args = parser.parse_args()
    repo = os.path.abspath(args.repo)
    exe = os.path.abspath(args.frictionviz)
    git = shutil.which("git")
    tracked = []
    if git and os.path.exists(os.path.join(repo, ".git")):
        tracked = subprocess.run([git, "-C", repo, "ls-files"], stdout=subprocess.PIPE, check=True,
                                 text=True).stdout.split("\n")
    if not [p for p in tracked if p]:
        # Not a git checkout (an exported tree): every file but build trees and hidden folders other than .ci.
        for root, dirs, files in os.walk(repo):
            rel = os.path.relpath(root, repo)
            dirs[:] = [d for d in dirs if not (rel == "." and (d.startswith("build") or
                                                                (d.startswith(".") and d != ".ci")))]
            tracked += [os.path.normpath(os.path.join(rel, f)) for f in files]
    tracked = [p for p in tracked if p]
    check_layout(repo, tracked)
    check_commands(repo, exe, set(args.compared))
    print(f"docs_check: {len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
