#!/usr/bin/env python3
"""Re-run every `$ homerun …` example in README.md and docs/*.md and write
what the program prints under it, where that differs (tests/readme.rs checks
the same rules: a line ending in "…" is a cut, a line of "…" alone stands for
the rest); and replace each screen of the explorer that no insta snapshot
holds any more by the snapshot most like it. A convenience for developers
after a change of output: read the diff before committing. Not used by the
tests.

    cargo build --release && python3 scripts/doc-examples.py
"""
import glob
import os
import subprocess
import tempfile

# The release binary (`cargo build --release`).
BINARY = "target/release/homerun"


def runnable(command):
    # A file of the repository's own (tests/data/) runs as written.
    committed = all(".csv" not in w or w.startswith("tests/data/") for w in command.split())
    return committed and not any(s in command for s in ("$", "\\", ".toml", "--svg"))


def agrees(shown, printed):
    for i, line in enumerate(shown):
        if line == "…":
            return True
        if i >= len(printed):
            return False
        p = printed[i]
        same = p.startswith(line[:-1].rstrip()) if line.endswith("…") else p == line
        if not (same or ("/.config/homerun" in line and p)):
            return False
    return len(printed) == len(shown)


def rewrite(shown, printed):
    new = []
    for i, line in enumerate(shown):
        if line == "…":
            new.append("…")
            return new
        if i >= len(printed):
            return new
        p = printed[i]
        if line.endswith("…") and len(p) > len(line) - 1:
            new.append(p[: len(line) - 1].rstrip() + "…")
        else:
            new.append(p)
    return new + printed[len(shown):]


def run(args, home):
    out = subprocess.run([BINARY] + args, capture_output=True, text=True,
                         env={**os.environ, "XDG_CONFIG_HOME": home})
    return [l.rstrip() for l in (out.stdout + out.stderr).splitlines()]


def snapshots():
    found = []
    for path in sorted(glob.glob("tests/**/snapshots/*.snap", recursive=True)):
        body = open(path).read().split("---\n", 2)[2]
        found.append([l.strip('"').rstrip() for l in body.splitlines()])
    return found


def screens(path, shots):
    """Each screen block (first line "┌ Inputs") no snapshot holds, replaced
    by the most similar snapshot of the same size."""
    import difflib
    text = open(path).read()
    blocks = text.split("```")
    changed = 0
    for k in range(1, len(blocks), 2):
        lines = blocks[k].split("\n")
        body = [l.rstrip() for l in lines[1:]]
        while body and body[-1] == "":
            body.pop()
        if not body or not body[0].startswith("┌ Inputs") or body in shots:
            continue
        # The second line: the first (the tab bar) may end short of the edge.
        same_size = [s for s in shots if len(s) == len(body) and len(s[1]) == len(body[1])]
        if not same_size:
            print(f"{path}: a screen of {len(body)} lines that no snapshot has; left as it is")
            continue
        best = max(same_size, key=lambda s: difflib.SequenceMatcher(None, "\n".join(s), "\n".join(body)).ratio())
        blocks[k] = lines[0] + "\n" + "\n".join(best) + "\n"
        changed += 1
    if changed:
        open(path, "w").write("```".join(blocks))
        print(f"{path}: {changed} screen(s) replaced")


def main():
    shots = snapshots()
    for path in ["README.md"] + sorted(glob.glob("docs/*.md")):
        screens(path, shots)
    home = tempfile.mkdtemp()
    for path in ["README.md"] + sorted(glob.glob("docs/*.md")):
        lines = open(path).read().split("\n")
        out, i, in_block, changed = [], 0, False, 0
        while i < len(lines):
            line = lines[i]
            out.append(line)
            i += 1
            if line.startswith("```"):
                in_block = not in_block
                continue
            if not (in_block and line.startswith("$ homerun")):
                continue
            command = line[len("$ homerun"):]
            shown = []
            while i < len(lines) and not lines[i].startswith("```") and not lines[i].startswith("$ homerun"):
                shown.append(lines[i].rstrip())
                i += 1
            if not runnable(command):
                out.extend(shown)
                continue
            tail = None
            if "| tail -" in command:
                command, n = command.split("| tail -")
                tail = int(n.strip())
            printed = run(command.split(), home)
            if tail is not None:
                printed = printed[-tail:]
            if agrees(shown, printed):
                out.extend(shown)
            else:
                changed += 1
                out.extend(rewrite(shown, printed))
        if changed:
            open(path, "w").write("\n".join(out))
            print(f"{path}: {changed} example(s) rewritten")


main()
