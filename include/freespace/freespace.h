#pragma once

// The core of freespace in one header: meshes and problems read from files, the exact
// collision test, the exact free space (locate, clearance, the free cell graph, the
// faces of its slices), certified motions and translations inside a slice's face.
// Internal stages have headers of their own under freespace/.

#include "freespace/collision/exact_collision_checker.h"
#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"
#include "freespace/problem/path_file.h"
#include "freespace/problem/planar_problem.h"
#include "freespace/space/face_path.h"
#include "freespace/space/free_space.h"
#include "freespace/space/max_clearance_path.h"
#include "freespace/space/motion_checker.h"
#include "freespace/topology/cell_graph.h"
#include "freespace/topology/slice_faces.h"
