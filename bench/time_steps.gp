# Charts of bench/time_steps (doc/performance.md, "Time stepping"): error
# against the time step and against the wall time, per integrator. Run
# from the directory holding time_steps_period.csv and time_steps_creep.csv:
#   gnuplot -e "doc_dir='/path/to/doc'" /path/to/bench/time_steps.gp
# Writes doc_dir/time_steps_period.png and doc_dir/time_steps_creep.png.
if (!exists("doc_dir")) doc_dir = '../../doc'

set terminal pngcairo size 1100,480 font ",11"
set datafile separator comma
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid
set key bottom right

# Series are selected by the integrator name in column 1; names with a
# blank cannot be words of a "for [name in ...]" list, so they are the
# variables n1..n3 of each study.
select(name, column_value) = strcol(1) eq name ? column_value : 1/0
name(i) = value(sprintf("n%d", i))

do for [study in "period creep"] {
  csv = 'time_steps_'.study.'.csv'
  if (study eq "period") {
    n1 = "newmark"; n2 = "midpoint"; n3 = "backward euler"
  } else {
    n1 = "quasi-static"; n2 = "backward euler"; n3 = "newmark"
  }
  set output doc_dir.'/time_steps_'.study.'.png'
  set multiplot layout 1,2 title (study eq "period" ? \
    "Cantilever started in its first mode (N = 50): period error vs the discrete mode's period" : \
    "Creep of a standard-linear-solid cantilever: max error of P L^3 J(t)/3I at t_c, 3t_c, 10t_c")
  set xlabel (study eq "period" ? "time step / period" : "time step / t_c")
  set ylabel "relative error"
  error_column = study eq "period" ? 5 : 4
  plot for [i=1:3] csv every ::1 \
    using (1.0/$2):(select(name(i), column(error_column))) \
    with linespoints pt 7 title name(i)
  set xlabel "wall time per run (s), median of repeats"
  plot for [i=1:3] csv every ::1 \
    using (column(error_column + 1)):(select(name(i), column(error_column))) \
    with linespoints pt 7 title name(i)
  unset multiplot
}
