#!/usr/bin/env python3
"""Test of tools/promote-references.sh in a scratch git repository: each refusal (no message,
unknown name, no candidate, not a PNG, identical candidate, other changes staged, one bad name
among good ones) leaves the repository as it was, and a promotion makes exactly one commit
holding only the named reference files, with the message.
Usage: test_promote_references.py SOURCE_DIR. Exits 77 (skipped) when git is missing."""
import os, shutil, subprocess, sys, tempfile

SKIP = 77
PNG = b"\x89PNG\r\n\x1a\n"
failures = []


def check(name, ok, detail=""):
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else f": {detail}"))
    if not ok:
        failures.append(name)


def main():
    source = sys.argv[1]
    if not shutil.which("git"):
        print("SKIP: git not installed")
        return SKIP
    with tempfile.TemporaryDirectory() as repo:
        def git(*args):
            return subprocess.run(["git", "-C", repo, *args], capture_output=True, text=True,
                                  check=True).stdout

        def write(path, data):
            full = os.path.join(repo, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "wb") as f:
                f.write(data)

        def read(path):
            with open(os.path.join(repo, path), "rb") as f:
                return f.read()

        git("init", "-q")
        git("config", "user.name", "Test")
        git("config", "user.email", "test@example.invalid")
        git("config", "commit.gpgsign", "false")
        os.makedirs(os.path.join(repo, "tools"))
        script = os.path.join(repo, "tools", "promote-references.sh")
        shutil.copy(os.path.join(source, "tools", "promote-references.sh"), script)
        write("tests/reference/demo.png", PNG + b"old demo")
        write("tests/reference/csg.png", PNG + b"old csg")
        write("tests/gpu/test_new.cpp", b'imageMatchesReference(image, "fresh");\n')
        write("README.md", b"readme\n")
        write(".gitignore", b"build/\n")
        git("add", "-A")
        git("commit", "-q", "-m", "start")

        def promote(*args):
            return subprocess.run(["bash", script, *args], capture_output=True, text=True,
                                  cwd=repo)

        def head():
            return git("rev-parse", "HEAD").strip()

        def refused(name, args, says):
            before, status = head(), git("status", "--porcelain")
            r = promote(*args)
            check(name + ": refused", r.returncode != 0, f"exit {r.returncode}")
            check(name + ": says why", says in r.stderr, r.stderr.strip())
            check(name + ": no commit", head() == before)
            check(name + ": nothing changed", git("status", "--porcelain") == status,
                  git("status", "--porcelain"))

        candidates = "build/test-output/"
        write(candidates + "demo.candidate.png", PNG + b"new demo")
        refused("no message", ["demo"], "message")
        refused("blank message", ["-m", "  ", "demo"], "message")
        refused("unknown name", ["-m", "why", "nonesuch"], "nonesuch")
        refused("a path as name", ["-m", "why", "../README"], "not a reference name")
        refused("no candidate", ["-m", "why", "csg"], "no candidate")
        refused("one bad name among good ones", ["-m", "why", "demo", "nonesuch"], "nonesuch")
        write(candidates + "csg.candidate.png", b"GIF89a")
        refused("not a PNG", ["-m", "why", "csg"], "not a PNG")
        write(candidates + "csg.candidate.png", PNG + b"old csg")
        refused("identical candidate", ["-m", "why", "csg"], "identical")
        write("README.md", b"edited\n")
        git("add", "README.md")
        refused("other changes staged", ["-m", "why", "demo"], "README.md")
        git("reset", "-q", "README.md")
        write("tests/reference/demo.png", PNG + b"hand edit")
        refused("reference edited by hand", ["-m", "why", "demo"], "uncommitted")
        git("checkout", "-q", "--", "tests/reference/demo.png")

        # A promotion of an existing and a new reference: one commit, only those two files.
        write(candidates + "fresh.candidate.png", PNG + b"fresh")
        before = head()
        r = promote("-m", "the sky is darker: fog now starts at 10 m", "demo", "fresh")
        check("promotion succeeds", r.returncode == 0, r.stderr.strip())
        check("one commit", git("rev-list", "--count", f"{before}..HEAD").strip() == "1",
              git("log", "--oneline", f"{before}..HEAD"))
        files = git("show", "--name-only", "--format=", "HEAD").split()
        check("only the references", files == ["tests/reference/demo.png",
                                                "tests/reference/fresh.png"], files)
        message = git("log", "-1", "--format=%B")
        check("the message", "the sky is darker: fog now starts at 10 m" in message and
              "demo" in message and "fresh" in message, message)
        check("the candidate's bytes", read("tests/reference/demo.png") == PNG + b"new demo")
        check("README's edit left alone", read("README.md") == b"edited\n" and
              git("status", "--porcelain").strip() == "M README.md",
              git("status", "--porcelain"))
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
