set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_asymmetric_free_dt0.00078125.svg'
set datafile separator ','
set title 'Relative energy error, asymmetric_free, dt = 0.00078125 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_asymmetric_free_direct_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_asymmetric_free_munjiza_rk4_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_asymmetric_free_zvw_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_asymmetric_free_zvw_corrected_dt0.00078125.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
