#!/bin/sh
# doc-snapshot.sh FILE LINE NEW  -- renew a snapshot of the book
#
# LINE is the line of FILE that holds a marker
#   <!-- snapshot[ATTRS]: COMMAND @ COMMIT, MACHINE; sha SHA -->
# (tests/doc-tables.awk says what it is) and NEW a file: what COMMAND
# prints now.  The block or table that follows the marker is replaced by
# NEW's lines, COMMIT becomes the current commit (git rev-parse --short
# HEAD) and SHA the checksum of the block's lines (the first 12 hex digits
# of their sha256), which tests/cases-doc.sh (doc-tables) checks.
# tests/doc-snapshots.sh --update (make doc-snapshots UPDATE=1) reruns
# COMMAND and calls this script: a snapshot is renewed from its command,
# never edited by hand.  Run from the top of the repository.
set -eu
F=${1:?usage: doc-snapshot.sh FILE LINE NEW}; N=${2:?usage: doc-snapshot.sh FILE LINE NEW}
NEW=${3:?usage: doc-snapshot.sh FILE LINE NEW}
[ -f "$NEW" ] || { echo "doc-snapshot: no file $NEW" >&2; exit 1; }
sed -n "${N}p" "$F" | grep -q '^<!-- snapshot\(\[[^]]*\]\)\{0,1\}: .* @ .*; sha [0-9a-f]* -->$' ||
  { echo "doc-snapshot: $F:$N is not a snapshot marker" >&2; exit 1; }
commit=$(git rev-parse --short HEAD)
tmp=$(mktemp); trap 'rm -f "$tmp" "$tmp.b"' EXIT
# the block: a fenced block or a pipe table right after the marker
awk -v n="$N" -v new="$NEW" -v blk="$tmp.b" '
  function emit(   i, l) {
    if (new != "") { nb = 0; while ((getline l < new) > 0) body[++nb] = l }
    printf "" > blk
    for (i = 1; i <= nb; i++) print body[i] > blk
    close(blk)
    print "@@MARK@@"; if (fence) print open
    for (i = 1; i <= nb; i++) print body[i]
    if (fence) print "```"
  }
  NR < n { print; next }
  NR == n { next }
  state == 0 { if (/^```/) { state = 1; fence = 1; open = $0; next }
               if (/^\|/) { state = 1; fence = 0 }
               else { print "doc-snapshot: no block right after the marker" > "/dev/stderr"; exit 1 } }
  state == 1 && fence && /^```/ { state = 2; emit(); next }
  state == 1 && !fence && !/^\|/ { state = 2; emit(); print; next }
  state == 1 { body[++nb] = $0; next }
  { print }
  END { if (state == 1) emit() }' "$F" > "$tmp"
sha=$(sha256sum < "$tmp.b" | cut -c1-12)
at="s/ @ [^,;]*\([,;]\)/ @ $commit\1/;"
mark=$(sed -n "${N}p" "$F" | sed "$at s/; sha [0-9a-f]* -->\$/; sha $sha -->/")
awk -v m="$mark" '$0 == "@@MARK@@" { print m; next } { print }' "$tmp" > "$F"
echo "doc-snapshot: $F:$N: sha $sha"
