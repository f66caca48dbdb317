# Fig. 6 (paper §2.3, Eq. 5): master and client CPG outputs with the client synchronised
# (alpha = 1: it follows the master) and free (alpha = 0: each CPG at its own period).
# Variables: data (step, sync_/free_ master_/client_ x1/x2), master_period, client_period.
load dir.'common.gp'
# Head room above 1 keeps the key off the curves.
set yrange [-0.05:1.3]
set ytics 0, 0.2, 1
set xlabel 'time step'
set key top right horizontal font ',10'
set multiplot layout 2, 2 title sprintf('CPG outputs: master p = %d, client p = %d', master_period, client_period) font ',14'
do for [mode in 'sync free'] {
  do for [neuron in 'x1 x2'] {
    set title sprintf('(%s) %s, neuron %s', mode eq 'sync' ? 'a' : 'b', mode eq 'sync' ? 'synchronised (α = 1)' : 'not synchronised (α = 0)', neuron)
    set ylabel sprintf('output %s', neuron)
    plot data using 'step':(column(mode.'_master_'.neuron)) with linespoints lw 2 pt 7 ps 0.5 lc rgb blue title sprintf('master (p = %d)', master_period), \
         data using 'step':(column(mode.'_client_'.neuron)) with linespoints lw 2 dt 2 pt 6 ps 0.7 lc rgb red title sprintf('client (p = %d)', client_period)
  }
}
unset multiplot
