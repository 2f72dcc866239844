set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_fast_spin_dt6.25e-05.svg'
set datafile separator ','
set title 'Relative energy error, fast_spin, dt = 6.25e-05 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_fast_spin_direct_dt6.25e-05.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_fast_spin_munjiza_rk4_dt6.25e-05.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_fast_spin_zvw_dt6.25e-05.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_fast_spin_zvw_corrected_dt6.25e-05.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
