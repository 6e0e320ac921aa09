#!/usr/bin/env bash
# The documentation stands alone: every relative link or image in README.md
# and doc/*.md must name a file inside the repository that exists, and no
# page may mention a path above the repository (../ outside a link that
# stays inside). Web addresses (citations) are allowed.
#
# Usage: bash doc_links.sh REPOSITORY_ROOT
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 1 ] || fail "usage: doc_links.sh REPOSITORY_ROOT"
root="$(cd "$1" && pwd)"
start_test doc_links

python3 - "$root" <<'PY' || fail "the documentation has links that leave the repository or point nowhere"
import os, re, sys
root = sys.argv[1]
pages = [os.path.join(root, "README.md")] + sorted(
    os.path.join(root, "doc", f) for f in os.listdir(os.path.join(root, "doc")) if f.endswith(".md"))
bad = 0
links = 0
for page in pages:
    text = open(page).read()
    here = os.path.dirname(page)
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"^[a-z]+://", target) or target.startswith("#"):
            continue
        links += 1
        path = os.path.normpath(os.path.join(here, target.split("#")[0]))
        rel = os.path.relpath(page, root)
        if not path.startswith(root + os.sep):
            print(f"FAIL: {rel}: link '{target}' leaves the repository"); bad += 1
        elif not os.path.exists(path):
            print(f"FAIL: {rel}: link '{target}' names no file"); bad += 1
    for m in re.finditer(r"\.\./shared|(?<![\w.])\.\./\.\./", text):
        print(f"FAIL: {os.path.relpath(page, root)}: mentions '{m.group(0)}'"); bad += 1
    # A merge that left its conflict markers in a page.
    for m in re.finditer(r"^(<{7}|>{7}) ", text, re.M):
        print(f"FAIL: {os.path.relpath(page, root)}: merge conflict marker '{m.group(1)}'"); bad += 1
print(f"  {len(pages)} pages, {links} relative links checked")
sys.exit(1 if bad else 0)
PY
pass "README.md and doc/*.md link only to files inside the repository"
