# stability_charts.gp - charts of fixel-stability's wide tables.
#   gnuplot -e "dir='docs/stability'" host_sim/scripts/stability_charts.gp
# Each <sweep>_max.dat: column 1 the swept parameter, then max and p99 texel
# error per method (affine, subdiv8, subdiv16, subdiv32, exact, auto);
# errors below 1e-9 are written as 1e-9 so the log axis can show them.
if (!exists("dir")) dir = 'docs/stability'
set terminal pngcairo size 900,560 noenhanced font ",10"
set datafile commentschars "#"
set logscale y
set format y "%g"
set yrange [1e-6:1e5]
set ylabel "max |(u,v) - exact| (level-0 texels)"
set key outside right top
set grid
names = "affine subdiv8 subdiv16 subdiv32 exact auto"
# reference lines: the 1/64, 1/8 and 1 texel thresholds of summary.csv
set arrow from graph 0, first 1.0/64 to graph 1, first 1.0/64 nohead dt 3 lc rgb "#888888"
set arrow from graph 0, first 0.125 to graph 1, first 0.125 nohead dt 3 lc rgb "#888888"
set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb "#888888"

plotsweep(f, t, xl) = sprintf("set output '%s/%s.png'; set title '%s'; set xlabel '%s'", dir, f, t, xl)

set logscale x
eval plotsweep("depth", "Depth ratio far w / near w across a 256x256 quad (1/w varies diagonally)", "far w / near w")
plot for [i=1:6] dir.'/depth_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
eval plotsweep("eyeplane", "Vertex approaching the eye plane (w_near / w -> inf); beyond q16: clipped to the guard band", "2 / w of the third vertex")
plot for [i=1:6] dir.'/eyeplane_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
eval plotsweep("screen", "Screen extent of a triangle around the target (>= 32767 px: clipped in double first)", "extent (px)")
plot for [i=1:6] dir.'/screen_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
eval plotsweep("sliver", "Slivers: 200 px long, 200/aspect px wide, v across", "aspect ratio")
plot for [i=1:6] dir.'/sliver_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
do for [w in "repeat mirror clamp"] {
  eval plotsweep("texcoord_".w, "u, v offset by B periods (2 periods across the quad), wrap ".w, "offset B + 1 (periods)")
  plot for [i=1:6] dir.'/texcoord_'.w.'_max.dat' using ($1+1):(column(2*i)) with linespoints title word(names, i)
  eval plotsweep("texcoord_wide_".w, "u, v from -B to +B periods across the quad, wrap ".w, "B (periods)")
  plot for [i=1:6] dir.'/texcoord_wide_'.w.'_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
}
eval plotsweep("range", "Texel range U across a floor-like quad times its depth ratio R (64-texel texture, u, v over U / 64 periods)", "U * R (texels)")
set xrange [1e3:3e10]
plot for [r in "10 100 1000 10000"] dir.'/range_r'.r.'_max.dat' using 1:10 with linespoints title 'exact, R = '.r, \
     for [r in "10 100 1000 10000"] dir.'/range_r'.r.'_max.dat' using 1:12 with lines dt 2 title 'auto, R = '.r, \
     3.2 * x / 2**30 + 2**-16 with lines lc rgb "#000000" title "bound 3.2 * 2^-30 U R + 2^-16"
set xrange [*:*]
unset logscale x
eval plotsweep("grazing", "Plane turned away from the viewer (2x2 at distance 3, 8 periods)", "angle (degrees)")
plot for [i=1:6] dir.'/grazing_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
eval plotsweep("texsize", "Texture size (0:1x1 1:1x1024 2:1024x1 3:2x8 4:16x16 5:64x256 6:256x64 7:512^2 8:1024^2 9:1024x2)", "case")
plot for [i=1:6] dir.'/texsize_max.dat' using 1:(column(2*i)) with linespoints title word(names, i)
