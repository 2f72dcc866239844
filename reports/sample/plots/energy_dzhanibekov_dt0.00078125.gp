set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_dzhanibekov_dt0.00078125.svg'
set datafile separator ','
set title 'Relative energy error, dzhanibekov, dt = 0.00078125 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_dzhanibekov_direct_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_dzhanibekov_munjiza_rk4_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_dzhanibekov_zvw_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_dzhanibekov_zvw_corrected_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
