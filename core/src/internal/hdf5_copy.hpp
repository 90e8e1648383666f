// Copying an HDF5 group's contents into another group of another file (a
// child process's run into the results file, ResultsFileWriter::copy_run).
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

namespace pb::internal {

// Copies the links `names` of `from` (datasets and groups, with their own
// attributes, chunk by chunk as stored: H5Ocopy) and every attribute of
// `from` itself into `to`, in that order. Throws Hdf5Error naming `object`.
void copy_group_contents(hid_t from, hid_t to, const std::vector<std::string>& names,
                         const std::string& object);

}  // namespace pb::internal
