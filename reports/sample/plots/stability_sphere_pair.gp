set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'stability_sphere_pair.svg'
set title 'sphere_pair: stability limit against damping ratio'
set xlabel 'zeta'
set ylabel 'dt (s)'
set logscale y
set grid
set key outside right
names = 'cayley direct exact_splitting fincham munjiza_rk4 no_gyro no_squish omelyan richardson rozmanov_kusalik spiral zvw zvw_corrected'
file = 'stability_sphere_pair.dat'
plot for [i=1:words(names)] file index (i-1) using 1:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 title word(names, i), file index 0 using 1:4 with lines dt 2 lc 'black' title 'Peng (eq. 46)'
