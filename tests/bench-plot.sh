#!/usr/bin/env bash
# bench-plot.sh BENCH.csv OUTDIR — one SVG per function from pfbench's CSV:
# speed (x, ns per element of the array form, log scale) against max error
# (y, ULP on the seeded sample, log scale), one labelled point per candidate,
# one panel per input domain, and the Pareto front (no other candidate is
# both faster and more accurate) as a staircase through the best points;
# pfmath's own curve (issue 13) is a second staircase through the pfmath
# points alone: exact, fast and the accuracy ladder's levels (pfmath-L<U>).
# Writes OUTDIR/bench-<func>.svg (and .png with BENCH_PLOT_PNG=1).  Needs gnuplot (Debian gnuplot-nox) and awk.
set -eu
csv=${1:?usage: bench-plot.sh BENCH.csv OUTDIR}
out=${2:?usage: bench-plot.sh BENCH.csv OUTDIR}
command -v gnuplot >/dev/null || { echo "bench-plot.sh: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
md="$(dirname "$csv")/bench.md"
cpu=$(sed -n 's/^- CPU: \([^(]*\).*/\1/p' "$md" 2>/dev/null | sed 's/ *$//')
date=$(sed -n 's/^- date: \([^;]*\);.*/\1/p' "$md" 2>/dev/null)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# CSV -> one whitespace-separated file per (function, domain):
#   ns  ulp  pareto  class  label
# class: 0 pfmath, 1 pfmath-fast, 2 glibc, 3 libmvec, 4 sleef-u10, 5 sleef-u35,
# 6 pfmath-L<U> (a ladder level)
# Only measured ULP rows (absent candidates and fixed-point LSB rows have no
# place on a ULP axis; they are in bench.md).
awk -v dir="$tmp" '
function parse(line,   i, c, q, f) {      # RFC 4180 subset: quoted fields, no embedded quotes
  n = 0; f = ""; q = 0
  for (i = 1; i <= length(line); i++) {
    c = substr(line, i, 1)
    if (c == "\"") q = !q
    else if (c == "," && !q) { F[++n] = f; f = "" }
    else f = f c
  }
  F[++n] = f
}
NR == 1 { parse($0); for (i = 1; i <= n; i++) col[F[i]] = i; next }
{
  parse($0)
  if (F[col["unit"]] != "ulp" || F[col["status"]] != "ok") next
  t = F[col["thr_med"]] + 0; e = F[col["max_ulp"]]
  if (t <= 0 || e == "inf" || e == "nan" || e + 0 <= 0) next
  name = F[col["candidate"]]; isa = F[col["isa"]]
  lad = name ~ /^pfmath-L[0-9]+$/
  cls = name == "pfmath" ? 0 : name == "pfmath-fast" ? 1 : lad ? 6 : name == "glibc" ? 2 : \
        name == "libmvec" ? 3 : name == "sleef-u10" ? 4 : 5
  short = name == "pfmath" ? "pf" : name == "pfmath-fast" ? "pf-fast" : lad ? substr(name, 8) : \
          name == "libmvec" ? "mvec" : name == "sleef-u10" ? "sleef10" : name == "sleef-u35" ? "sleef35" : name
  if (isa == "avx512") short = short "/512"; else if (isa == "avx2") short = short "/256"
  else if (isa == "sse2") short = short "/128"; else if (isa == "dispatch") short = short "/disp"
  fn = F[col["func"]]; dom = F[col["domain"]]
  file = dir "/" fn "@" dom ".dat"
  if (!(file in seen)) { seen[file] = 1; order[++nf] = file; desc[file] = F[col["domain_desc"]] }
  printf "%s %s %s %d %s\n", t, e, F[col["pareto"]], cls, short > file
}
END { for (i = 1; i <= nf; i++) print order[i] "\t" desc[order[i]] > (dir "/index") }
' "$csv"

[ -s "$tmp/index" ] || { echo "bench-plot.sh: no measured rows in $csv" >&2; exit 1; }

# Axis ranges and label positions for one panel.  gnuplot does not move
# labels out of each other's way, so this does, greedily: points from left
# to right, each label tried right, left, above and below its point (in
# graph-fraction units, a character ~ 0.012 wide and a line 0.03 high on a
# 640x520 panel) and put at the first spot that overlaps no label placed
# before it and no point; a label pushed away gets a thin leader line.
place_labels() {
  sort -g "$1" | awk '
  function lg(v) { return log(v) / log(10) }
  function fl(v) { return v == int(v) ? v : (v < 0 ? int(v) - 1 : int(v)) }
  function overlap(x0, y0, x1, y1, self,   k) {
    if (x0 < 0 || x1 > 1 || y0 < 0 || y1 > 1) return 1
    for (k = 1; k <= nb; k++)
      if (k != self && x0 < BX1[k] && x1 > BX0[k] && y0 < BY1[k] && y1 > BY0[k]) return 1
    return 0
  }
  { n++; X[n] = $1; Y[n] = $2; L[n] = $5 }
  END {
    xmin = xmax = lg(X[1]); ymin = ymax = lg(Y[1])
    for (i = 2; i <= n; i++) {
      if (lg(X[i]) < xmin) xmin = lg(X[i]); if (lg(X[i]) > xmax) xmax = lg(X[i])
      if (lg(Y[i]) < ymin) ymin = lg(Y[i]); if (lg(Y[i]) > ymax) ymax = lg(Y[i])
    }
    x0 = fl(xmin - 0.1); x1 = -fl(-(xmax + 0.6)); y0 = fl(ymin - 0.3); y1 = -fl(-(ymax + 0.4))
    printf "set xrange [%g:%g]\nset yrange [%g:%g]\n", 10^x0, 10^x1, 10^y0, 10^y1
    cw = 0.0118; lh = 0.032; gap = 0.014
    # the points are obstacles, with a label height of room above and
    # below, so that no label sits right over the point of another candidate
    # (box i belongs to point i: its own label may come close to it)
    for (i = 1; i <= n; i++) {
      gx[i] = (lg(X[i]) - x0) / (x1 - x0); gy[i] = (lg(Y[i]) - y0) / (y1 - y0)
      nb++; BX0[nb] = gx[i] - 0.008; BX1[nb] = gx[i] + 0.008
      BY0[nb] = gy[i] - 0.012 - lh; BY1[nb] = gy[i] + 0.012 + lh
    }
    split("1 0 1 1 1 -1 -1 0 -1 1 -1 -1 0 1.3 0 -1.3 1 2 1 -2 -1 2 -1 -2 1 3 1 -3 -1 3 -1 -3", C, " ")
    for (i = 1; i <= n; i++) {
      w = cw * length(L[i]); best = 0
      for (c = 1; c <= 16 && !best; c++) {
        sx = C[2 * c - 1]; sy = C[2 * c]
        lx = sx > 0 ? gx[i] + gap : sx < 0 ? gx[i] - gap - w : gx[i] - w / 2
        ly = gy[i] + sy * lh
        if (!overlap(lx, ly - lh / 2, lx + w, ly + lh / 2, i)) best = c
      }
      if (!best) { best = 1; sx = 1; sy = 0; lx = gx[i] + gap; ly = gy[i] }
      nb++; BX0[nb] = lx; BX1[nb] = lx + w; BY0[nb] = ly - lh / 2; BY1[nb] = ly + lh / 2
      printf "set label \"%s\" at graph %.4f, graph %.4f left font \",8\" front\n", L[i], lx, ly
      if (sy * sy > 1.5)   # pushed away: a leader line from the point
        printf "set arrow from graph %.4f, graph %.4f to graph %.4f, graph %.4f nohead lw 0.5 lc rgb \"#aaaaaa\"\n", \
               gx[i], gy[i], (sx > 0 ? lx : lx + w), ly
    }
  }'
}

for fn in $(cut -f1 "$tmp/index" | sed 's|.*/||; s|@.*||' | awk '!s[$0]++'); do
  panels=$(grep -c "/$fn@" "$tmp/index" || true)
  width=$((640 * panels))
  {
    echo "set terminal svg size $width,520 dynamic enhanced font 'sans,11' background rgb 'white'"
    echo "set output '$out/bench-$fn.svg'"
    echo "set logscale xy"
    echo "set grid xtics ytics mxtics mytics lc rgb '#dddddd'"
    echo "set xlabel 'ns per element (array form; log scale)'"
    echo "set ylabel 'max error, ULP (seeded sample; log scale)'"
    echo "set key outside bottom center horizontal font ',9'"
    echo "set multiplot layout 1,$panels title \"$fn: speed against error — ${cpu:-this CPU}, ${date:-}\\n{/=9 /128, /256, /512: array form for SSE2, AVX2, AVX-512; no suffix: scalar calls in a loop}\" font ',13'"
    grep "/$fn@" "$tmp/index" | while IFS=$'\t' read -r file desc; do
      # gnuplot single-quoted strings: double any quote
      d=$(printf '%s' "$desc" | sed "s/'/''/g")
      echo "set title 'on $d'"
      echo "unset label; unset arrow"
      place_labels "$file"
      awk '$3 == 1' "$file" | sort -g > "$file.front"
      # pfmath's curve: its points that no other pfmath point beats in both
      awk '$4 == 0 || $4 == 1 || $4 == 6' "$file" | sort -g -k1,1 -k2,2 |
        awk 'NR == 1 || $2 < best { print; best = $2 }' > "$file.ours"
      echo "plot \\"
      echo "  '$file.front' using 1:2 with steps lw 2 lc rgb '#999999' title 'Pareto front', \\"
      echo "  '$file.ours' using 1:2 with steps lw 1.5 dt 2 lc rgb '#1f4e9e' title 'pfmath curve', \\"
      echo "  '$file' using (\$4 == 0 ? \$1 : NaN):2 with points pt 7 ps 1.1 lc rgb '#1f4e9e' title 'pfmath', \\"
      echo "  '$file' using (\$4 == 1 ? \$1 : NaN):2 with points pt 5 ps 1.0 lc rgb '#58a6ff' title 'pfmath fast', \\"
      echo "  '$file' using (\$4 == 6 ? \$1 : NaN):2 with points pt 6 ps 1.0 lc rgb '#1f4e9e' title 'pfmath ladder (L<U>: U ULP)', \\"
      echo "  '$file' using (\$4 == 2 ? \$1 : NaN):2 with points pt 9 ps 1.2 lc rgb '#000000' title 'glibc scalar', \\"
      echo "  '$file' using (\$4 == 3 ? \$1 : NaN):2 with points pt 11 ps 1.2 lc rgb '#2ca02c' title 'libmvec', \\"
      echo "  '$file' using (\$4 == 4 ? \$1 : NaN):2 with points pt 13 ps 1.1 lc rgb '#d62728' title 'SLEEF u10', \\"
      echo "  '$file' using (\$4 == 5 ? \$1 : NaN):2 with points pt 15 ps 1.1 lc rgb '#ff7f0e' title 'SLEEF u35'"
    done
    echo "unset multiplot"
  } > "$tmp/$fn.gp"
  gnuplot "$tmp/$fn.gp"
  echo "  SVG $out/bench-$fn.svg"
  if [ -n "${BENCH_PLOT_PNG:-}" ]; then   # a PNG beside it, for viewers without SVG
    sed -e "1s/.*/set terminal pngcairo size $width,520 enhanced font 'sans,10' background rgb 'white'/" \
        -e "2s/\.svg'/.png'/" "$tmp/$fn.gp" | gnuplot
  fi
done
