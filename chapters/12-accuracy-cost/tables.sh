#!/bin/sh
# strategies-table.sh -- this chapter's table of the strategies, as Markdown
#
#   sh chapters/12-accuracy-cost/strategies-table.sh [BUILD [CSV]]
#
# Summary 2b of bench/accuracy-cost.sh, made again from the runs it
# recorded (CSV: figures/accuracy-cost.csv, which make figures writes; the
# times are those of the machine that ran them): the time of the solve
# stage of each strategy over that of the fastest on the same run, median
# (min-max) over the runs of a dimension and a size.  A few seconds: no
# run, the table and the charts from the CSV (in BUILD/strategies-table).
B=${1:-build}
CSV=${2:-figures/accuracy-cost.csv}
OUT=$B/strategies-table
sh bench/accuracy-cost.sh "$B" --from "$CSV" --out "$OUT" 2> "$OUT.err" > /dev/null ||
  { cat "$OUT.err" >&2; exit 1; }
# "  2D  0-600  14  10.74 (1.05-28.27) 14  1.00 (1.00-1.00) 14 ..." ->
# "| 2D, ≤ 600 | 10.74 (1.05–28.27) | 1.00 (1.00–1.00) | ..."
awk '/^## 2b\./ { on = 1; next }
  on && /^  dim / { n = 0; for (i = 4; i <= NF; i++) s[++n] = $i
                    printf "| dofs |"; for (i = 1; i <= n; i++) printf " %s |", s[i]
                    printf "\n|---|"; for (i = 1; i <= n; i++) printf "---|"; printf "\n"; next }
  on && /^  [23]D / { r = $2; sub (/^0-/, "≤ ", r); sub (/^>=$/, "≥", r); j = 4
                      if (r == "≥") { r = "≥ " $3; j = 5 }
                      else if (r !~ /^≤/) sub (/-/, "–", r)
                      printf "| %s, %s |", $1, r
                      for (i = 1; i <= n; i++) {
                        if ($j == "-") { printf " — |"; j++; continue }
                        g = $(j + 1); sub (/-/, "–", g)
                        printf " %s %s |", $j, g; j += 3 }
                      printf "\n"; next }
  on && !/^  [23]D / && !/^##/ { on = 0 }' "$OUT/accuracy-cost.txt"
