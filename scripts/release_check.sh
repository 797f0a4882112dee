#!/usr/bin/env bash
# The release path, as .ci/run runs it (`make release-check`): build the sdist and the wheel, check their
# metadata, install the wheel with its [export,view] extras into a fresh venv without system site-packages, and
# run scripts/wheel_smoke.py from a temporary folder outside the repository with new empty HOME, XDG_CACHE_HOME
# and LUMINOUS_CACHE and no other LUMINOUS_* variable. Prints the artefacts' sizes and each step's time.
set -euo pipefail
cd "$(dirname "$0")/.."
REPO=$(pwd)
PY=${PY:-python3.11}
BUILDER=${BUILDER:-$REPO/.venv/bin/python}
WORK=$(mktemp -d /tmp/luminous-release.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
t0=$(date +%s)

echo "== python -m build (sdist and wheel)"
"$BUILDER" -m build --outdir "$WORK/dist" . >"$WORK/build.log" 2>&1 || { tail -50 "$WORK/build.log"; exit 1; }
if grep -i "BuildBackendWarning\|SetuptoolsDeprecationWarning" "$WORK/build.log"; then
  echo "the build warns (above): fix it before a release"; exit 1
fi
"$BUILDER" -m twine check --strict "$WORK"/dist/*
WHEEL=$(ls "$WORK"/dist/*.whl)
SDIST=$(ls "$WORK"/dist/*.tar.gz)
echo "wheel $(basename "$WHEEL"): $(stat -c %s "$WHEEL") bytes; sdist $(basename "$SDIST"): $(stat -c %s "$SDIST") bytes"
t1=$(date +%s)

echo "== a fresh venv (no system site-packages) with the wheel and its [export,view] extras"
"$PY" -m venv "$WORK/venv"
"$WORK/venv/bin/python" -m pip install --quiet --upgrade pip 2>&1 | { grep -v "^WARNING: Location" || true; }
"$WORK/venv/bin/python" -m pip install --quiet "$WHEEL[export,view]" 2>&1 | { grep -v "^WARNING: Location" || true; }
"$WORK/venv/bin/python" -c "import luminous_sim" || { echo "the wheel did not install"; exit 1; }
t2=$(date +%s)

echo "== the smoke script, from $WORK/run"
mkdir -p "$WORK/run" "$WORK/home" "$WORK/xdg" "$WORK/cache"
cp scripts/wheel_smoke.py "$WORK/smoke.py"
for var in $(compgen -e | grep '^LUMINOUS_' || true); do unset "$var"; done
unset PYTHONPATH PYTHONHOME VIRTUAL_ENV
cd "$WORK/run"
HOME="$WORK/home" XDG_CACHE_HOME="$WORK/xdg" LUMINOUS_CACHE="$WORK/cache" PATH="$WORK/venv/bin:$PATH" \
  "$WORK/venv/bin/python" -I "$WORK/smoke.py"
t3=$(date +%s)
echo "release check: build $((t1 - t0)) s, install $((t2 - t1)) s, smoke $((t3 - t2)) s, all $((t3 - t0)) s"
