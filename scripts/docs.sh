#!/usr/bin/env bash
# Builds the documentation site (docs/*.md, mkdocs.yml) with Debian's mkdocs and its Material theme
# into a folder that opens in a browser from disk, with no server (every page a file of its own,
# relative links; no web fonts, no search). A warning (a broken link, a page missing from the nav)
# fails the build, as the test docs_site does.
# Usage: scripts/docs.sh [OUT]    (default build/docs; open OUT/index.html)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/docs}
if ! command -v mkdocs >/dev/null; then
  echo "docs.sh: mkdocs is not installed: scripts/install-deps.sh installs it (or apt-get install mkdocs mkdocs-material)" >&2
  exit 1
fi
mkdocs build --quiet --strict --clean --config-file mkdocs.yml --site-dir "$out"
echo "docs.sh: the site is in $out: open file://$(cd "$out" && pwd)/index.html"
