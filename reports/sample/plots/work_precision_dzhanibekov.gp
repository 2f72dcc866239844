set terminal svg size 1200,480 dynamic noenhanced font 'sans,12'
set logscale xy
set format x '%g'
set format y '%.0e'
set grid
set key outside right
names = 'cayley direct exact_splitting fincham munjiza_rk4 no_gyro no_squish omelyan richardson rozmanov_kusalik spiral zvw zvw_corrected'
titles = 'cayley(1.97x) direct(1.00x) exact_splitting(18.55x) fincham(0.95x) munjiza_rk4(1.51x) no_gyro(0.79x) no_squish(2.81x) omelyan(2.51x) richardson(1.35x) rozmanov_kusalik(2.26x) spiral(0.98x) zvw(1.19x) zvw_corrected(1.26x)'
file = 'runs_dzhanibekov.dat'
set output 'work_precision_dzhanibekov.svg'
set multiplot layout 1,3 title 'dzhanibekov: omega_err_max against cost (legend: instructions per body-step / direct)'
set xlabel 'CPU time (s)'
set ylabel 'omega_err_max'
unset key
plot for [i=1:words(names)] file index (i-1) using 3:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(titles, i)
set xlabel 'force evaluations'
plot for [i=1:words(names)] file index (i-1) using 4:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(titles, i)
set xlabel 'scheme instructions (callgrind)'
set key outside right
plot for [i=1:words(names)] file index (i-1) using 5:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(titles, i)
unset multiplot
