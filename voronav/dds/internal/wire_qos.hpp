// The data representation every voronav DDS reader and writer allows: XCDR1 only. voronav's
// types are @final structs that Cyclone writes as XCDR1 anyway; saying so in the QoS keeps a
// writer that offers only XCDR2 from matching a voronav reader. This matters because the
// XCDR2 normalizer of Debian's Cyclone 0.10.2 reads and byte-swaps past the end of a sample that
// ends inside an 8-byte member (fixed upstream in 2023, cyclonedds pull request #1559; found by
// fuzz/fuzz_dds_sample.cpp, docs/dds.md, "Data representation").
#pragma once

#include <dds/dds.h>

namespace voronav::dds::internal {

inline void allow_xcdr1_only(dds_qos_t* q) {
  const dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  dds_qset_data_representation(q, 1, xcdr1);
}

}  // namespace voronav::dds::internal
