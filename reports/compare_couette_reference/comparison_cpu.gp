set terminal pngcairo size 900,600 noenhanced
set output 'reports/compare_couette_reference/comparison_cpu.png'
set title 'error vs CPU time: couette'
set xlabel 'CPU time [s]'
set ylabel 'final relative velocity error vs reference run'
set logscale x
set logscale y
set grid
set key below
set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05
plot 'reports/compare_couette_reference/comparison_cpu.dat' index 0 with linespoints title 'leapfrog', 0.0001 with lines dt 2 lc rgb 'gray40' title 'error 0.0001'
