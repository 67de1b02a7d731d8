#!/usr/bin/env bash
# interphase-fe2d --help lists every entry its case reader takes, under its own group:
#   help_lists_entries.sh FE2D_EXECUTABLE CASE_READER_SOURCE MATERIAL_ENTRIES_SOURCE
# The entries are read from the reader's list of kinds (entry_kind_type('group.entry', ...)) and,
# for &joint, from the material group's entries (material_entry_kinds in the drivers' case
# reader, the source of &material and &joint alike), so an entry added to a reader and not to
# --help fails here. Prints "N entries listed" on success.
set -eo pipefail
exe=$1
source=$2
material_source=$3
help=$("$exe" --help)
# the &joint entries: the quoted names of material_entry_kinds' lists, and props
joint=$(awk '/function material_entry_kinds/ { on = 1 } on && /type\(entry_kind_type\)/ { exit }
             on { while (match($0, /'"'"'[a-z_0-9]+'"'"'/)) { print "joint." substr($0, RSTART + 1, RLENGTH - 2)
                                                          $0 = substr($0, RSTART + RLENGTH) } }' "$material_source")
[ -n "$joint" ] || { echo "no material entries found in $material_source"; exit 1; }
n=0
for e in $(grep -o "entry_kind_type('[a-z_]*[.][a-z_0-9]*'" "$source" | sed "s/entry_kind_type('//; s/'//") $joint joint.props; do
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
