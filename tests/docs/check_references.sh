#!/usr/bin/env bash
# Every reference in the tree resolves inside the tree:
#  1. no file names a design document that is not part of the repository (the all-capitals
#     names below) or points to a numbered issue of some tracker, and every plain mention of
#     docs/NAME.md names a page that exists;
#  2. every relative markdown link in a .md file ([text](path), [text](path#anchor), images,
#     reference-style definitions) names a file of the repository, and an anchor names a
#     heading of that file (GitHub's rule: lower case, punctuation dropped, spaces -> '-');
#  3. README.md links every page of docs/.
# Files are those git tracks, or, outside a git checkout, every file but build output.
#
#   check_references.sh ROOT          check the tree at ROOT; exit 0 clean, 1 with one line
#                                     per problem (FILE:LINE: what)
#   check_references.sh --self-test   run the check on small trees with known problems
set -u

pattern_words() {
  # Assembled from pieces so that this file does not match itself.
  local c="CONTRACT" f="FIGURES" e="ERRATA"
  printf '%s' "${c}\\.md|${f}\\.md|${e}|[Ii]ssue #?[0-9]"
}

list_files() {  # ROOT -> NUL-separated relative paths
  local root=$1
  if git -C "$root" rev-parse --show-toplevel >/dev/null 2>&1 &&
     [ "$(cd "$root" && git rev-parse --show-toplevel)" = "$(cd "$root" && pwd -P)" ]; then
    git -C "$root" ls-files -z
  else
    (cd "$root" && find . \( -path './build*' -o -path './out' -o -path './results' -o -name .git \) -prune \
        -o -type f -print0 | sed -z 's|^\./||')
  fi
}

check_tree() {
  local root=$1 problems=0 self
  self=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)/$(basename "${BASH_SOURCE[0]}")
  local -a files=()
  while IFS= read -r -d '' f; do
    [ -f "$root/$f" ] || continue                      # deleted in the work tree
    [ "$(cd "$root" && realpath "$f")" = "$self" ] && continue
    files+=("$f")
  done < <(list_files "$root")
  if [ ${#files[@]} -eq 0 ]; then
    echo "check_references: no files found under $root" >&2
    return 1
  fi

  # 1. Names of documents outside the repository, and issue numbers.
  local hits
  hits=$(cd "$root" && printf '%s\0' "${files[@]}" | xargs -0 grep -H -I -n -E "$(pattern_words)" -- 2>/dev/null)
  if [ -n "$hits" ]; then
    printf '%s\n' "$hits" | sed 's/^\([^:]*:[0-9]*\):.*/\1: refers to a document or issue outside the repository/'
    problems=$((problems + $(printf '%s\n' "$hits" | wc -l)))
  fi

  # Plain mentions of a page of docs/ (in comments, help texts, specs) name an existing page.
  local mention
  while IFS= read -r mention; do
    local f=${mention%%:*} rest=${mention#*:}
    local n=${rest%%:*} page=${rest#*:}
    if [ ! -f "$root/$page" ]; then
      echo "$f:$n: mentions $page, which the repository does not hold"
      problems=$((problems + 1))
    fi
  done < <(cd "$root" && printf '%s\0' "${files[@]}" | xargs -0 grep -H -I -n -o -E 'docs/[A-Za-z0-9_./-]+\.md' -- 2>/dev/null)

  # 2. Markdown links. awk prints "LINE<TAB>TARGET" for every relative link outside code.
  local md target line path anchor dir resolved
  for md in "${files[@]}"; do
    case "$md" in *.md) ;; *) continue ;; esac
    dir=$(dirname "$md")
    while IFS=$'\t' read -r line target; do
      path=${target%%#*}
      anchor=
      [ "$path" != "$target" ] && anchor=${target#*#}
      if [ -z "$path" ]; then
        resolved=$md
      else
        resolved=$(realpath -m --relative-to="$root" "$root/$dir/$path" 2>/dev/null)
      fi
      if [ -z "$resolved" ] || [ "${resolved#../}" != "$resolved" ] || [ ! -e "$root/$resolved" ]; then
        echo "$md:$line: link '$target' does not resolve to a file in the repository"
        problems=$((problems + 1))
        continue
      fi
      if [ -f "$root/$resolved" ] && ! printf '%s\n' "${files[@]}" | grep -qxF "$resolved" &&
         [ ! -d "$root/$resolved" ]; then
        echo "$md:$line: link '$target' names a file the repository does not hold"
        problems=$((problems + 1))
        continue
      fi
      if [ -n "$anchor" ]; then
        if [ "${resolved%.md}" = "$resolved" ] ||
           ! slugs "$root/$resolved" | grep -qxF "$anchor"; then
          echo "$md:$line: link '$target': no heading '#$anchor' in $resolved"
          problems=$((problems + 1))
        fi
      fi
    done < <(links "$root/$md")
  done

  # 3. The README links every page of docs/.
  if [ -f "$root/README.md" ]; then
    local listed
    listed=$(links "$root/README.md" | cut -f2 | sed 's/#.*//' | while IFS= read -r t; do
      [ -n "$t" ] && realpath -m --relative-to="$root" "$root/$t"; done)
    for md in "${files[@]}"; do
      case "$md" in docs/*.md) ;; *) continue ;; esac
      if ! printf '%s\n' "$listed" | grep -qxF "$md"; then
        echo "README.md: does not link $md"
        problems=$((problems + 1))
      fi
    done
  fi

  if [ $problems -gt 0 ]; then
    echo "check_references: $problems reference(s) do not resolve inside the repository" >&2
    return 1
  fi
  echo "check_references: ${#files[@]} files, every reference resolves"
  return 0
}

# Relative link targets of a markdown file, as "LINE<TAB>TARGET", outside fenced code blocks
# and inline code spans.
links() {
  awk '
    /^[ \t]*(```|~~~)/ { fence = !fence; next }
    fence { next }
    {
      s = $0
      gsub(/`[^`]*`/, "", s)                                  # inline code
      if (match(s, /^[ \t]*\[[^]]+\]:[ \t]*[^ \t]+/)) {       # [name]: target
        t = substr(s, RSTART, RLENGTH); sub(/^[ \t]*\[[^]]+\]:[ \t]*/, "", t); emit(t)
      }
      while (match(s, /\]\([^)]*\)/)) {                       # [text](target "title")
        t = substr(s, RSTART + 2, RLENGTH - 3)
        s = substr(s, RSTART + RLENGTH)
        sub(/^[ \t]*</, "", t); sub(/>[ \t]*$/, "", t)
        sub(/[ \t]+"[^"]*"[ \t]*$/, "", t)
        emit(t)
      }
    }
    function emit(t) {
      if (t == "" || t ~ /^[a-zA-Z][a-zA-Z0-9+.-]*:/) return  # http:, https:, mailto:, ...
      printf "%d\t%s\n", NR, t
    }
  ' "$1"
}

# GitHub anchors of the headings of a markdown file.
slugs() {
  awk '
    /^[ \t]*(```|~~~)/ { fence = !fence; next }
    fence { next }
    /^#+[ \t]/ {
      h = $0; sub(/^#+[ \t]+/, "", h); sub(/[ \t]+#*[ \t]*$/, "", h)
      h = tolower(h)
      gsub(/[^a-z0-9 _-]/, "", h)
      gsub(/ /, "-", h)
      n = seen[h]++
      print (n ? h "-" n : h)
    }
  ' "$1"
}

self_test() {
  local tmp rc=0
  tmp=$(mktemp -d) || return 1
  trap 'rm -rf "$tmp"' RETURN
  local w
  w=$(pattern_words)
  mkdir -p "$tmp/good/docs" "$tmp/bad1/docs" "$tmp/bad2/docs" "$tmp/bad3/docs" "$tmp/bad4" "$tmp/bad5" "$tmp/bad6"
  # A clean tree: links to files, anchors, directories, external links, links inside code.
  cat > "$tmp/good/README.md" <<'EOF'
# Top
See [the rules](docs/rules.md), [a heading](docs/rules.md#colour-and-alpha), [here](#top),
[a folder](docs/), [the web](https://example.org/x.md) and `[not a link](nowhere.md)`.
[ref]: docs/rules.md
```
[inside code](missing.md)
```
EOF
  printf '# Rules\n\n## Colour and alpha\n\nBack to the [README](../README.md).\n' > "$tmp/good/docs/rules.md"
  # Each bad tree has exactly one problem.
  cp -r "$tmp/good/." "$tmp/bad1/"; echo "[gone](docs/missing.md)" >> "$tmp/bad1/README.md"
  cp -r "$tmp/good/." "$tmp/bad2/"; echo "[gone](docs/rules.md#no-such-heading)" >> "$tmp/bad2/README.md"
  cp -r "$tmp/good/." "$tmp/bad3/"; printf '// see %s\n' "$(echo "$w" | cut -d'|' -f1 | tr -d '\\')" > "$tmp/bad3/code.cpp"
  cp -r "$tmp/good/." "$tmp/bad4/"; printf '# the workloads of %s 4\n' "is""sue" > "$tmp/bad4/bench.cpp"  # a tracker number
  cp -r "$tmp/good/." "$tmp/bad5/"; printf '# Orphan\n' > "$tmp/bad5/docs/orphan.md"
  cp -r "$tmp/good/." "$tmp/bad6/"; printf '// see docs/nothere.md\n' > "$tmp/bad6/code.cpp"
  if ! check_tree "$tmp/good" >/dev/null; then
    echo "self-test: a clean tree was rejected:"; check_tree "$tmp/good"; rc=1
  fi
  local b
  for b in bad1 bad2 bad3 bad4 bad5 bad6; do
    if check_tree "$tmp/$b" >/dev/null 2>&1; then
      echo "self-test: tree $b has a dangling reference but passed"; rc=1
    fi
  done
  [ $rc -eq 0 ] && echo "self-test: the check accepts the clean tree and rejects all six bad ones"
  return $rc
}

if [ "${1:-}" = "--self-test" ]; then
  self_test
  exit $?
fi
if [ $# -ne 1 ] || [ ! -d "$1" ]; then
  echo "usage: check_references.sh ROOT | --self-test" >&2
  exit 2
fi
check_tree "$(cd "$1" && pwd -P)"
