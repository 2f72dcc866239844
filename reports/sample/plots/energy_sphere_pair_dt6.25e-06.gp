set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_sphere_pair_dt6.25e-06.svg'
set datafile separator ','
set title 'Relative energy error, sphere_pair, dt = 6.25e-06 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_sphere_pair_direct_dt6.25e-06.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_sphere_pair_munjiza_rk4_dt6.25e-06.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_sphere_pair_zvw_dt6.25e-06.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_sphere_pair_zvw_corrected_dt6.25e-06.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
