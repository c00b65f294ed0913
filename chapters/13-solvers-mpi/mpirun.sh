# mpirun.sh -- the program of chapter 13 on N MPI processes    [chapter 13]
#
#   sh chapters/13-solvers-mpi/mpirun.sh [BUILD [N]]   (from the repository
#                                 root; BUILD: build, N: 2 by default)
#
# Runs mpirun -n N BUILD/chapters/13-solvers-mpi with the flags Open MPI
# may need: --oversubscribe (fewer free cores than processes) and, when
# run as root, --allow-run-as-root.  Process 0 prints; on N > 1 processes
# the others serve its petsc strategy, and the program runs its part 1
# only.  With N = 1 the output is that of build/chapters/13-solvers-mpi.
B=${1:-build}
N=${2:-2}
set -- mpirun
if mpirun --version 2>&1 | grep -q "Open MPI"; then
  set -- "$@" --oversubscribe
  [ "$(id -u)" = 0 ] && set -- "$@" --allow-run-as-root
fi
exec "$@" -n "$N" "$B/chapters/13-solvers-mpi"
