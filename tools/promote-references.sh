#!/usr/bin/env bash
# Promotes reviewed candidate reference images into tests/reference/ and commits them. The GPU
# tests write <build>/test-output/<name>.candidate.png when a reference comparison fails under
# RMSC_UPDATE_REFERENCES=1; after looking at it (and at <name>.diff.png), run
#   tools/promote-references.sh -m "what changed in the picture and why" NAME...
# Each invocation makes exactly one commit holding only those reference files. It refuses (and
# changes nothing) without a message, when anything else is staged, for a name no test uses, for
# a name without a candidate, and for a candidate identical to the committed reference.
# -b DIR: the build folder holding test-output/ (default: build in the repository root).
set -euo pipefail

usage() {
  echo "usage: $0 -m \"what changed in the picture and why\" [-b BUILD_DIR] NAME..." >&2
  exit 2
}
refuse() {
  echo "promote-references: $*; nothing promoted" >&2
  exit 1
}

message=""
build=""
while getopts "m:b:h" option; do
  case "$option" in
    m) message="$OPTARG" ;;
    b) build="$OPTARG" ;;
    *) usage ;;
  esac
done
shift $((OPTIND - 1))
[[ -n "${message//[[:space:]]/}" ]] ||
  refuse "a message (-m) saying what changed in the picture and why is required"
(($# > 0)) || usage

root="$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)"
build="${build:-$root/build}"
outputs="$build/test-output"
png_signature="89504e470d0a1a0a"

# Every check first: a refusal leaves the repository as it was.
declare -A seen=()
paths=()
for name in "$@"; do
  [[ "$name" =~ ^[A-Za-z0-9_-]+$ ]] || refuse "'$name' is not a reference name (letters, digits, _ and -)"
  [[ -z "${seen[$name]:-}" ]] || refuse "'$name' is named twice"
  seen[$name]=1
  reference="tests/reference/$name.png"
  # Known: a reference of that name exists, or a GPU test names it (a new reference).
  if [[ ! -f "$root/$reference" ]] && ! grep -qF "\"$name\"" "$root"/tests/gpu/*.cpp; then
    refuse "no reference image or GPU test is called '$name'"
  fi
  candidate="$outputs/$name.candidate.png"
  [[ -f "$candidate" ]] ||
    refuse "no candidate $candidate (run the GPU tests with RMSC_UPDATE_REFERENCES=1)"
  [[ "$(head -c 8 "$candidate" | od -An -tx1 | tr -d ' \n')" == "$png_signature" ]] ||
    refuse "$candidate is not a PNG"
  [[ -z "$(git -C "$root" status --porcelain -- "$reference")" ]] ||
    refuse "$reference has uncommitted changes"
  if git -C "$root" cat-file -e "HEAD:$reference" 2>/dev/null &&
    git -C "$root" show "HEAD:$reference" | cmp -s - "$candidate"; then
    refuse "the candidate of '$name' is identical to the committed reference"
  fi
  paths+=("$reference")
done
if ! git -C "$root" diff --cached --quiet; then
  refuse "other changes are staged ($(git -C "$root" diff --cached --name-only | tr '\n' ' '))"
fi

restore() {
  git -C "$root" reset -q -- "${paths[@]}"
  for path in "${paths[@]}"; do
    if git -C "$root" cat-file -e "HEAD:$path" 2>/dev/null; then
      git -C "$root" checkout -q HEAD -- "$path"
    else
      rm -f "$root/$path"
    fi
  done
}

for name in "$@"; do
  cp "$outputs/$name.candidate.png" "$root/tests/reference/$name.png"
done
git -C "$root" add -- "${paths[@]}"
names="$(printf '%s, ' "$@")"
if ! git -C "$root" commit -q -m "Reference images ${names%, }: $message"; then
  restore
  refuse "git commit failed"
fi
git -C "$root" log -1 --stat --format="%h %s"
