# One table row per ladder file (mk/ladder.mk: $(LADDER_DIR)/ladder.md), read from
# the provenance pfmathgen --max-ulp writes (gen/float/ladder.c): function, level,
# template, order, cost, the confirming sweep's max ULP and worst input, and
# whether that sweep was exhaustive.
/^ \* Regenerate:/ { for (i = 1; i < NF; i++) if ($i == "--func") f = $(i + 1) }
/^ \* Ladder:/ { lvl = $4; sub(":", "", lvl); L = 1 }
L && /template,$/ { t = $(NF - 1) }
L && / order [0-9]+, cost / { o = $3; sub(",", "", o); c = $5 }
/^ \* Confirmed:/ { m = $4; w = $0; sub(/.* at /, "", w); sub(/ over .*/, "", w); getline; k = $0
  sub(/^ \* +/, "", k); sub(/[:(].*/, "", k)
  printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", f, lvl, t, o, c, m, w, k; exit }
