#!/usr/bin/env python3
"""The documentation's tests (README.md and docs/*.md; CTest label `docs`, test/docs/CMakeLists.txt).

  docs_check.py check    --root SRC [--commands-tested PAGE ...]
      Every link and image resolves (files; anchors as both mkdocs and GitHub name a heading);
      docs/ pages link only inside docs/ (the built site holds nothing else); every picture in
      docs/images is shown by some Markdown file; every `<!-- shows: FILE -->` block is FILE as it
      is; every `<!-- runnable ... -->` marker stands before a fenced block; a page with runnable
      blocks has a docs_commands test (the pages given by --commands-tested); every line of a
      block run by ros_integration_test's ReadmeCommands is in that test's source.
  docs_check.py commands --root SRC --build BUILD [--shared DIR] [--timeout S] PAGE
      Runs PAGE's `<!-- runnable -->` blocks as printed, in order, each in its own
      `bash -e -o pipefail`, in a copy of the repository's root made of links (so that nothing is
      written into the checkout) whose build/release is BUILD, with build/release/bin on PATH.
  docs_check.py site     --root SRC
      `mkdocs build --strict` into a temporary folder (a warning fails), then every link and
      picture of every built page must be a file of the site, so that it opens from disk.
      Exit status 77 (CTest: skipped) where mkdocs is not installed.

Only the Python standard library: it runs before anything but Debian's python3 is installed.
"""

import argparse
import html.parser
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unicodedata
import urllib.parse

SKIP = 77
RUNNABLE = re.compile(r"^\s*<!--\s*runnable(?::\s*(.*?))?\s*-->\s*$")
SHOWS = re.compile(r"^\s*<!--\s*shows:\s*(\S+)\s*-->\s*$")
FENCE = re.compile(r"^(\s*)(```+|~~~+)\s*([\w+-]*)")
ROS_RUNNER = "ros_integration_test ReadmeCommands"
ROS_TEST_SOURCE = "src/ros/test/integration/readme_commands_test.cpp"


def pages(root):
    """README.md and every docs/*.md, as paths relative to root."""
    docs = sorted(f for f in os.listdir(os.path.join(root, "docs")) if f.endswith(".md"))
    return ["README.md"] + ["docs/" + f for f in docs]


def read(root, rel):
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        return f.read()


class Block:
    def __init__(self, page, line, marker, shows, lang, text):
        self.page, self.line, self.marker, self.shows, self.lang, self.text = page, line, marker, shows, lang, text

    def where(self):
        return f"{self.page}:{self.line}"


def blocks(page, text, errors):
    """The fenced code blocks of a page, each with the marker comment on the line before it."""
    lines = text.split("\n")
    out = []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, lang = m.group(1), m.group(2), m.group(3)
        start = i
        body = []
        i += 1
        while i < len(lines) and not lines[i].strip().startswith(fence):
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i].lstrip())
            i += 1
        if i == len(lines):
            errors.append(f"{page}:{start + 1}: a code block that never closes")
        i += 1
        prev = lines[start - 1] if start > 0 else ""
        r, s = RUNNABLE.match(prev), SHOWS.match(prev)
        out.append(Block(page, start + 1, (r.group(1) or "") if r else None, s.group(1) if s else None, lang,
                         "\n".join(body) + "\n"))
    # A marker not right before a fence would mark nothing: say so.
    fence_lines = {b.line - 1 for b in out}
    for n, line in enumerate(lines, 1):
        if (RUNNABLE.match(line) or SHOWS.match(line)) and n not in fence_lines:
            errors.append(f"{page}:{n}: `{line.strip()}` is not on the line right before a ``` code block")
    return out


def strip_code(text):
    """The text without fenced blocks and inline code (links there are not links)."""
    text = re.sub(r"(?ms)^\s*(```+|~~~+).*?^\s*\1\s*$", lambda m: "\n" * m.group(0).count("\n"), text)
    return re.sub(r"`[^`\n]*`", "", text)


def heading_texts(text):
    out = []
    for line in strip_code_blocks_only(text).split("\n"):
        m = re.match(r"^(#{1,6})\s+(.*?)\s*#*\s*$", line)
        if m:
            out.append(m.group(2))
    return out


def strip_code_blocks_only(text):
    return re.sub(r"(?ms)^\s*(```+|~~~+).*?^\s*\1\s*$", "", text)


def plain(heading):
    """A heading's text as rendered: no backticks, emphasis or link syntax."""
    h = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    h = h.replace("`", "")
    h = re.sub(r"(\*\*|__|\*)", "", h)
    return h


def mkdocs_slug(heading):
    # Python-Markdown's toc.slugify (what mkdocs gives the heading's id).
    v = unicodedata.normalize("NFKD", plain(heading)).encode("ascii", "ignore").decode("ascii")
    v = re.sub(r"[^\w\s-]", "", v).strip().lower()
    return re.sub(r"[-\s]+", "-", v)


def github_slug(heading):
    v = plain(heading).strip().lower()
    v = re.sub(r"[^\w\- ]", "", v)
    return v.replace(" ", "-")


def anchors(text, slug):
    seen = {}
    out = set()
    for h in heading_texts(text):
        s = slug(h)
        n = seen.get(s, 0)
        seen[s] = n + 1
        out.add(s if n == 0 else (f"{s}_{n}" if slug is mkdocs_slug else f"{s}-{n}"))
    return out


LINK = re.compile(r"(!?)\[((?:[^\[\]]|\[[^\]]*\])*)\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML_REF = re.compile(r"<(?:img|a)\b[^>]*?\b(?:src|href)=\"([^\"]+)\"", re.I)


def links(text):
    body = strip_code(text)
    for m in LINK.finditer(body):
        yield m.group(1) == "!", m.group(3), body.count("\n", 0, m.start()) + 1
    for m in HTML_REF.finditer(body):
        yield False, m.group(1), body.count("\n", 0, m.start()) + 1


def check(args):
    root = os.path.abspath(args.root)
    errors = []
    texts = {p: read(root, p) for p in pages(root)}
    tested = set(args.commands_tested or [])
    ros_source = None
    shown_images = set()
    for page, text in texts.items():
        page_dir = os.path.dirname(page)
        # Links and pictures.
        for image, target, line in links(text):
            url = urllib.parse.urlparse(target)
            if url.scheme or url.netloc or target.startswith("mailto:"):
                continue
            path, frag = urllib.parse.unquote(url.path), url.fragment
            where = f"{page}:{line}: {'picture' if image else 'link'} `{target}`"
            if path:
                resolved = os.path.normpath(os.path.join(page_dir, path))
                if resolved.startswith(".."):
                    errors.append(f"{where} leaves the repository")
                    continue
                if page.startswith("docs/") and not resolved.startswith("docs" + os.sep):
                    errors.append(f"{where} points outside docs/: the built site does not have {resolved}; "
                                  "name a source file as code (`src/x/README.md`) instead of linking it")
                    continue
                if not os.path.exists(os.path.join(root, resolved)):
                    errors.append(f"{where}: {resolved} does not exist")
                    continue
                if image:
                    shown_images.add(resolved)
            else:
                resolved = page
            if frag:
                if not resolved.endswith(".md"):
                    errors.append(f"{where}: an anchor into a file that is not Markdown")
                    continue
                target_text = texts.get(resolved) or read(root, resolved)
                if frag not in anchors(target_text, mkdocs_slug):
                    errors.append(f"{where}: {resolved} has no heading whose mkdocs id is #{frag}")
                elif frag not in anchors(target_text, github_slug):
                    errors.append(f"{where}: {resolved}'s heading for #{frag} gets another id on GitHub; "
                                  "reword the heading so that both agree")
        # Marked blocks.
        page_blocks = blocks(page, text, errors)
        runnable = [b for b in page_blocks if b.marker is not None]
        if any(b.marker == "" for b in runnable) and page not in tested:
            errors.append(f"{page} has runnable command blocks but no docs_commands test: configure the build "
                          "again (test/docs/CMakeLists.txt registers one per page that has them)")
        for b in page_blocks:
            if b.shows:
                try:
                    want = read(root, b.shows)
                except OSError:
                    errors.append(f"{b.where()}: shows {b.shows}, which does not exist")
                    continue
                if b.text != want:
                    errors.append(f"{b.where()}: the block is not {b.shows} as it is (copy the file into it again)")
            if b.marker not in (None, "", ROS_RUNNER):
                errors.append(f"{b.where()}: unknown runnable marker `{b.marker}` (plain `runnable`, or "
                              f"`runnable: {ROS_RUNNER}`)")
            if b.marker == ROS_RUNNER:
                if ros_source is None:
                    src = read(root, ROS_TEST_SOURCE)
                    ros_source = [re.sub(r"\\(.)", lambda e: {"n": "\n", "t": "\t"}.get(e.group(1), e.group(1)), m.group(1))
                                  for m in re.finditer(r'"((?:[^"\\\n]|\\.)*)"', src)]
                for line in b.text.split("\n"):
                    line = line.strip()
                    if line and not line.startswith("#") and not any(line in lit for lit in ros_source):
                        errors.append(f"{b.where()}: `{line}` is marked as run by {ROS_RUNNER}, but "
                                      f"{ROS_TEST_SOURCE} does not run it")
    # Every picture is shown somewhere (a layer README counts).
    for dirpath, dirnames, filenames in os.walk(root):
        rel_dir = os.path.relpath(dirpath, root)
        dirnames[:] = [d for d in dirnames if not (d.startswith(".") or d.startswith("build") or d in ("out", "node_modules"))]
        for f in filenames:
            if f.endswith(".md") and not (rel_dir == "." and f == "README.md") and not rel_dir == "docs":
                rel = os.path.normpath(os.path.join(rel_dir, f))
                for image, target, _ in links(read(root, rel)):
                    if image:
                        shown_images.add(os.path.normpath(os.path.join(rel_dir, urllib.parse.unquote(target))))
    for f in sorted(os.listdir(os.path.join(root, "docs/images"))):
        if os.path.join("docs", "images", f) not in shown_images:
            errors.append(f"docs/images/{f} is shown by no Markdown file: show it on a page, or remove it")
    for e in errors:
        print("FAIL", e)
    n_links = sum(1 for t in texts.values() for _ in links(t))
    print(f"{len(texts)} pages, {n_links} links and pictures checked: {len(errors)} problem(s)")
    return 1 if errors else 0


def make_tree(root, build, shared, into):
    """A copy of the repository's root made of links: <into>/mechsim/<entry> -> root/<entry>, its
    build/release -> build, and <into>/shared -> shared (the pages' ../shared)."""
    tree = os.path.join(into, "mechsim")
    os.makedirs(os.path.join(tree, "build"))
    for entry in os.listdir(root):
        if entry.startswith(".") or entry.startswith("build") or entry == "out":
            continue
        os.symlink(os.path.join(root, entry), os.path.join(tree, entry))
    os.symlink(os.path.abspath(build), os.path.join(tree, "build", "release"))
    if shared and os.path.isdir(shared):
        os.symlink(os.path.abspath(shared), os.path.join(into, "shared"))
    return tree


def commands(args):
    root = os.path.abspath(args.root)
    errors = []
    page_blocks = [b for b in blocks(args.page, read(root, args.page), errors) if b.marker == ""]
    if errors:
        print("\n".join("FAIL " + e for e in errors))
        return 1
    if not page_blocks:
        print(f"{args.page}: no runnable command blocks")
        return 0
    failed = 0
    with tempfile.TemporaryDirectory(prefix="mechsim_docs_") as tmp:
        tree = make_tree(root, args.build, args.shared, tmp)
        env = dict(os.environ)
        env["PATH"] = os.path.join(tree, "build", "release", "bin") + os.pathsep + env.get("PATH", "")
        env["PWD"] = tree
        for b in page_blocks:
            print(f"== {b.where()} (in {tree}):\n{b.text}", flush=True)
            t0 = time.monotonic()
            # The block runs in a process group of its own, which is ended afterwards (also after a
            # time-out), so that nothing it started outlives it.
            p = subprocess.Popen(["/bin/bash", "-e", "-o", "pipefail", "-c", b.text], cwd=tree, env=env,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
            try:
                raw, _ = p.communicate(timeout=args.timeout)
                status = p.returncode
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                raw, _ = p.communicate()
                status = f"timed out after {args.timeout:.0f} s"
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            out = raw.decode("utf-8", "replace")
            tail = "\n".join(out.rstrip().split("\n")[-25:])
            dt = time.monotonic() - t0
            if status == 0:
                print(f"   ok, {dt:.1f} s", flush=True)
            else:
                failed += 1
                what = f"exit status {status}" if isinstance(status, int) else status
                print(f"FAIL {b.where()}: {what} after {dt:.1f} s; the last lines:\n{tail}", flush=True)
    print(f"{args.page}: {len(page_blocks) - failed} of {len(page_blocks)} runnable blocks ran as printed")
    return 1 if failed else 0


class Refs(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.refs = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value and ((name == "href" and tag in ("a", "link")) or (name == "src" and tag in ("img", "script"))):
                self.refs.append(value)


def site(args):
    root = os.path.abspath(args.root)
    mkdocs = shutil.which("mkdocs")
    if not mkdocs:
        print("docs_site: skipped: mkdocs is not installed (scripts/install-deps.sh installs it: Debian's "
              "mkdocs and mkdocs-material)")
        return SKIP
    with tempfile.TemporaryDirectory(prefix="mechsim_site_") as out:
        p = subprocess.run([mkdocs, "build", "--strict", "--config-file", os.path.join(root, "mkdocs.yml"),
                            "--site-dir", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        log = re.sub(r"\x1b\[[0-9;]*m", "", p.stdout.decode("utf-8", "replace"))
        warnings = [l for l in log.split("\n") if l.startswith(("WARNING", "ERROR"))]
        # mkdocs says only INFO about a page left out of the nav; here it is an error too (a page
        # the site's menu does not reach).
        if "not included in the \"nav\"" in log:
            warnings.append("a page of docs/ is not in mkdocs.yml's nav")
        if p.returncode != 0 or warnings:
            print(log)
            print(f"FAIL mkdocs build --strict: exit status {p.returncode}; " + "; ".join(warnings))
            return 1
        problems = []
        n_pages = n_refs = 0
        for dirpath, _, filenames in os.walk(out):
            for f in filenames:
                # 404.html is a web server's page (its links are absolute by design); from disk a
                # browser never shows it.
                if not f.endswith(".html") or f == "404.html":
                    continue
                n_pages += 1
                path = os.path.join(dirpath, f)
                parser = Refs()
                with open(path, encoding="utf-8") as h:
                    parser.feed(h.read())
                for ref in parser.refs:
                    url = urllib.parse.urlparse(ref)
                    if url.scheme or url.netloc or not url.path:
                        continue
                    n_refs += 1
                    target = os.path.normpath(os.path.join(dirpath, urllib.parse.unquote(url.path)))
                    rel = os.path.relpath(path, out)
                    if url.path.startswith("/"):
                        problems.append(f"{rel}: `{ref}` is absolute: it does not open from disk")
                    elif os.path.isdir(target):
                        problems.append(f"{rel}: `{ref}` is a folder: from disk a browser lists it instead of a page")
                    elif not os.path.isfile(target):
                        problems.append(f"{rel}: `{ref}` is not a file of the site")
        for pr in problems:
            print("FAIL", pr)
        if not os.path.isfile(os.path.join(out, "index.html")):
            problems.append("no index.html")
            print("FAIL the site has no index.html")
        print(f"mkdocs build --strict: no warnings; {n_pages} pages, {n_refs} local links checked: "
              f"{len(problems)} problem(s)")
        return 1 if problems else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="what", required=True)
    c = sub.add_parser("check")
    c.add_argument("--root", required=True)
    c.add_argument("--commands-tested", nargs="*")
    r = sub.add_parser("commands")
    r.add_argument("--root", required=True)
    r.add_argument("--build", required=True, help="the build folder (its bin/ holds mechsim)")
    r.add_argument("--shared", default="")
    r.add_argument("--timeout", type=float, default=300.0, help="seconds per block")
    r.add_argument("page")
    s = sub.add_parser("site")
    s.add_argument("--root", required=True)
    args = ap.parse_args()
    return {"check": check, "commands": commands, "site": site}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
