set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_fast_spin_dt0.001.svg'
set datafile separator ','
set title 'Relative energy error, fast_spin, dt = 0.001 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_fast_spin_direct_dt0.001.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_fast_spin_munjiza_rk4_dt0.001.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_fast_spin_zvw_dt0.001.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_fast_spin_zvw_corrected_dt0.001.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
