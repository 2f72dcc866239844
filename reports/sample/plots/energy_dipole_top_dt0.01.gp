set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_dipole_top_dt0.01.svg'
set datafile separator ','
set title 'Relative energy error, dipole_top, dt = 0.01 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_dipole_top_direct_dt0.01.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_dipole_top_munjiza_rk4_dt0.01.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_dipole_top_zvw_dt0.01.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_dipole_top_zvw_corrected_dt0.01.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
