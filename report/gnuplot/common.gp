# Settings every figure shares; loaded first by each script. The caller (report/figures.cpp)
# has set the terminal, the output and the variables each script documents, `data` among them.
set encoding utf8
set datafile separator comma
set datafile columnheaders
set style fill solid 1.0 noborder
set grid lc rgb '#dddddd' lw 1
# The paper's colours: blue = stance / support (Fig. 2); TC green, CTr red, FTi blue (Fig. 9);
# beta = 0 blue, annealing red, greedy green (Fig. 14).
blue = '#1f5fbf'
red = '#d62728'
green = '#2ca02c'
grey = '#7f7f7f'
orange = '#e69f00'
