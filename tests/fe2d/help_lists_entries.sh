#!/usr/bin/env bash
# interphase-fe2d --help lists every entry its case reader takes, under its own group:
#   help_lists_entries.sh FE2D_EXECUTABLE CASE_READER_SOURCE
# The entries are read from the reader's list of kinds (entry_kind_type('group.entry', ...)), so an
# entry added to the reader and not to --help fails here. Prints "N entries listed" on success.
set -eo pipefail
exe=$1
source=$2
help=$("$exe" --help)
n=0
for e in $(grep -o "entry_kind_type('[a-z_]*[.][a-z_0-9]*'" "$source" | sed "s/entry_kind_type('//; s/'//"); do
  group=${e%%.*}
  entry=${e#*.}
  # the words after "&group" up to the next "&...", punctuation aside
  if ! printf '%s\n' "$help" | awk -v g="&$group" -v k="$entry" '
      { gsub(/[,;()]/, " ")
        for (i = 1; i <= NF; i++) {
          if ($i == g) on = 1
          else if ($i ~ /^&/) on = 0
          else if (on && $i == k) found = 1
        } }
      END { exit !found }'; then
    echo "interphase-fe2d --help does not list $e"
    exit 1
  fi
  n=$((n + 1))
done
[ "$n" -gt 0 ] || { echo "no entries found in $source"; exit 1; }
echo "$n entries listed"
