#!/usr/bin/env bash
# Test data that Debian packages ship but that mechsim neither installs nor copies: fetched into
# build/test-data by the tests' command (scripts/test.sh); a test whose file is absent skips and
# names this script.
#   olinda_dem_utm25s.tif  a public DEM the project was not built on: elevation of Olinda, Brazil
#                          (UTM zone 25S, 111 x 111 float samples, ~90 m apart, -1..88 m), from
#                          the R package stars (Apache-2.0) as Debian 12 packages it
#                          (r-cran-stars 0.6-0-4). Only the .deb is downloaded, R is not installed.
# Each file's SHA-256 is checked: a different file is refused rather than tested against.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/test-data
mkdir -p "$out"
name=olinda_dem_utm25s.tif
sha=6954774429a04c827c8330943ee43a176a29d52be2f220100f352894c4b9f173
if [[ -f "$out/$name" ]] && echo "$sha  $out/$name" | sha256sum -c --status; then
  exit 0
fi
tmp=$(mktemp -d /tmp/mechsim_fetch_XXXXXX)
trap 'rm -rf "$tmp"' EXIT
# apt-get download runs as the _apt user where it can write the folder.
chmod 777 "$tmp"
if ! (cd "$tmp" && apt-get download r-cran-stars >/dev/null 2>"$tmp/apt.log"); then
  echo "fetch-test-data: cannot download Debian's r-cran-stars ($(tail -1 "$tmp/apt.log")); the tests" \
       "that need $name will skip" >&2
  exit 0
fi
dpkg-deb --fsys-tarfile "$tmp"/r-cran-stars_*.deb |
  tar -x -C "$tmp" "./usr/lib/R/site-library/stars/tif/$name"
if ! echo "$sha  $tmp/usr/lib/R/site-library/stars/tif/$name" | sha256sum -c --status; then
  echo "fetch-test-data: $name from $(basename "$tmp"/r-cran-stars_*.deb) is not the file the tests" \
       "were written for (SHA-256 differs); they will skip" >&2
  exit 0
fi
mv "$tmp/usr/lib/R/site-library/stars/tif/$name" "$out/$name"
echo "fetch-test-data: $out/$name"
