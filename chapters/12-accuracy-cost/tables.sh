#!/bin/sh
# tables.sh -- this chapter's tables, as Markdown, from the recorded study
#
#   sh chapters/12-accuracy-cost/tables.sh [BUILD] TABLE [CSV]
#
# TABLE is one of the summaries of bench/accuracy-cost.sh:
#   targets     1: for each target error, the first level of each element
#               that reaches it, cheapest first (dofs, time of the run)
#   strategies  2b: the time of the solve stage of each strategy over that
#               of the fastest on the same run, median (min-max) over the
#               runs of a dimension and a size
#   split       3: where the time of the finest run of each element goes
#               (percent of the run)
#   rates       4: the observed rates against dofs and against h
#   agree       5: the largest difference of the errors between strategies
# made again from the runs the study recorded (CSV: figures/accuracy-cost.csv,
# which make figures writes).  The dofs, errors and rates do not depend on
# the machine; the times (and their ratios and shares) are those of the
# machine that made the CSV.  Under a second: no run, the study's table
# from the CSV (in BUILD/accuracy-tables).
B=build
case $1 in targets|strategies|split|rates|agree) ;; *) B=${1:-build}; shift ;; esac
T=${1:?tables.sh: which table (targets, strategies, split, rates, agree)?}
CSV=${2:-figures/accuracy-cost.csv}
OUT=$B/accuracy-tables
mkdir -p "$OUT" || exit 1
sh bench/accuracy-cost.sh "$B" --from "$CSV" --out "$OUT" 2> "$OUT.err" > /dev/null ||
  { cat "$OUT.err" >&2; exit 1; }
TXT=$OUT/accuracy-cost.txt
case $T in
targets)
  # "  manufactured2d  u <= 1e-4   tri6 L2 2178 dofs 0.030 s, quad8 L2 1666* dofs 0.031 s"
  # -> "| manufactured2d | u ≤ 1e-4 | tri6 L2: 2178 dofs, 0.030 s; quad8 L2: **1666** dofs, 0.031 s |"
  echo "| problem | target | the first level of each element that reaches it, cheapest first (dofs, time of the run; fewest dofs in bold) |"
  echo "|---|---|---|"
  awk '/^## 1\./ { on = 1; next } /^## [0-9]/ { on = 0 }
    on && /^  [a-z]/ { q = ($2 == "lambda") ? "$\\lambda$" : "$" $2 "$"
      line = $0; sub (/^ *[^ ]+ +[^ ]+ +<= +[^ ]+ +/, "", line)
      n = split (line, r, ", "); cell = ""
      for (i = 1; i <= n; i++) { split (r[i], w, " "); d = w[3]
        if (d ~ /\*$/) { sub (/\*$/, "", d); d = "**" d "**" }
        cell = cell (i > 1 ? "; " : "") w[1] " " w[2] ": " d " dofs, " w[5] " s" }
      printf "| %s | %s ≤ %s | %s |\n", $1, q, $4, cell }' "$TXT" ;;
strategies)
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
    on && !/^  [23]D / && !/^##/ { on = 0 }' "$TXT" ;;
split)
  echo "| run | dofs | strategy | run (s) | mesh | macro-mesh | pairing | contact | material | assembly | factorization | active set | rest of solve | post |"
  echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  awk '/^## 3\./ { on = 1; next } /^## [0-9]/ { on = 0 }
    on && /^  [a-z]/ && $1 != "run" { printf "| %s %s %s | %s | %s | %s |", $1, $2, $3, $4, $5, $6
      for (i = 8; i <= NF; i++) printf " %s |", $i; printf "\n" }' "$TXT" ;;
rates)
  echo '| run | $u$ against dofs | $\lambda$ against dofs | $u$ in $h$ | $\lambda$ in $h$ |'
  echo "|---|---:|---:|---:|---:|"
  awk '/^## 4\./ { on = 1; next } /^## [0-9]/ { on = 0 }
    on && /^  [a-z]/ && $1 != "run" { printf "| %s %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $6, $7 }' "$TXT" ;;
agree)
  awk '/^## 5\./ { on = 1; next } /^## [0-9]/ { on = 0 } on && /^  [0-9]/ { sub (/^  /, ""); print }' "$TXT" ;;
*) echo "tables.sh: no table '$T' (targets, strategies, split, rates, agree)" >&2; exit 2 ;;
esac
