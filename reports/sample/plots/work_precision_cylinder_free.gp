set terminal svg size 800,480 dynamic noenhanced font 'sans,12'
set logscale xy
set format x '%g'
set format y '%.0e'
set grid
set key outside right
names = 'cayley direct exact_splitting fincham munjiza_rk4 no_gyro no_squish omelyan richardson rozmanov_kusalik spiral zvw zvw_corrected'
file = 'runs_cylinder_free.dat'
set output 'work_precision_cylinder_free.svg'
set multiplot layout 1,2 title 'cylinder_free: omega_err_max against cost'
set xlabel 'CPU time (s)'
set ylabel 'omega_err_max'
unset key
plot for [i=1:words(names)] file index (i-1) using 3:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(names, i)
set xlabel 'force evaluations'
set key outside right
plot for [i=1:words(names)] file index (i-1) using 4:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(names, i)
unset multiplot
