// make_cluster() of a glint built without MPI: always a single process.
#include <glint/cluster/cluster.h>

namespace glint {

std::unique_ptr<Cluster> make_cluster(int& argc, char**& argv) {
    (void)argc;
    (void)argv;
    return make_single_process();
}

bool cluster_has_mpi() {
    return false;
}

}  // namespace glint
