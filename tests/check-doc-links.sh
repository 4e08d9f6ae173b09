#!/usr/bin/env bash
# Checks the links of README.md and docs/*.md, so that moving a section
# between them cannot leave a reader at a dead link:
#   ](#anchor)            a heading of the same file
#   ](path) ](path#anchor) a file or directory that exists, relative to the
#                          linking file; for a .md target, #anchor must be
#                          one of that file's headings
# Anchors follow GitHub's rule: the heading's text lowercased, every
# character but letters, digits, spaces, '-' and '_' dropped, spaces turned
# into '-', and a repeated anchor numbered -1, -2, ...  Web links (http:,
# https:, mailto:) are not checked.  One line per broken link; exit 1 if any.
# The ASan build skips this (the same script on the same files).
set -u
bin=@BIN@
case "$bin" in */asan*) echo "[  SKIPPED ] 1 test(s): the doc links are checked in the plain build only"; exit 0;; esac
root=$(pwd)
[ -f "$root/README.md" ] || { echo "run from the repository root"; exit 1; }
export LC_ALL=C.UTF-8

# anchors FILE: every heading's anchor, one a line (outside ``` fences)
anchors() {
  awk '/^```/ { fence = !fence; next } !fence && /^#+ / { sub(/^#+ +/, ""); sub(/ +#* *$/, ""); print }' "$1" |
    sed -E 's/.*/\L&/; s/[^[:alnum:] _-]//g; s/ /-/g' |
    awk '{ n = seen[$0]++; print (n ? $0 "-" n : $0) }'
}

pass=0; fail=0
for f in "$root/README.md" "$root"/docs/*.md; do
  rel=${f#"$root"/}
  dir=$(dirname "$f")
  own=$(anchors "$f")
  # every ](target) on every line, with its line number
  while IFS=: read -r line target; do
    case "$target" in http:* | https:* | mailto:*) continue;; esac
    path=${target%%#*}; anchor=
    case "$target" in *'#'*) anchor=${target#*#};; esac
    ok=1; why=
    if [ -z "$path" ]; then
      grep -qxF -- "$anchor" <<<"$own" || { ok=0; why="no heading with anchor #$anchor"; }
    elif [ ! -e "$dir/$path" ]; then
      ok=0; why="no such file: $path"
    elif [ -n "$anchor" ]; then
      case "$path" in
        *.md) anchors "$dir/$path" | grep -qxF -- "$anchor" || { ok=0; why="no heading with anchor #$anchor in $path"; };;
      esac
    fi
    if [ $ok -eq 1 ]; then pass=$((pass+1)); else fail=$((fail+1)); echo "[  FAILED  ] $rel:$line: ]($target): $why"; fi
  done < <(grep -no '\]([^) ]*)' "$f" | sed -E 's/^([0-9]+):\]\((.*)\)$/\1:\2/')
done
[ $((pass+fail)) -gt 0 ] || { echo "[  FAILED  ] no links found"; fail=1; }
echo "[  PASSED  ] $pass test(s)."
[ $fail -eq 0 ] || echo "[  FAILED  ] $fail test(s), listed above"
[ $fail -eq 0 ]
