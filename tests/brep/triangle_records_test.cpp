// The refinement's per-triangle records (triangle_records.h): a record is found only under the
// corners it was evaluated with, and records keep their place as the store grows.
#include <gtest/gtest.h>

#include <vector>

#include "triangle_records.h"

namespace cetview::brep {
namespace {

TEST(TriangleRecords, ARecordIsFoundUnderItsOwnCornersOnly) {
  TriangleRecords records;
  EXPECT_EQ(records.find(0, 1, 2, 3), nullptr) << "nothing reserved";
  records.reserve(10);
  EXPECT_EQ(records.find(5, 1, 2, 3), nullptr) << "reserved but never evaluated";
  TriangleRecord& r = records.at(5);
  r.v[0] = 1, r.v[1] = 2, r.v[2] = 3;
  r.deviation = 0.25f;
  ASSERT_NE(records.find(5, 1, 2, 3), nullptr);
  EXPECT_EQ(records.find(5, 1, 2, 3)->deviation, 0.25f);
  EXPECT_EQ(records.find(5, 2, 3, 1), nullptr) << "the same corners in another order: another triangle";
  EXPECT_EQ(records.find(5, 1, 2, 4), nullptr) << "a corner changed";
  EXPECT_EQ(records.find(1u << 30, 1, 2, 3), nullptr) << "beyond the store";
  records.clear();
  EXPECT_EQ(records.find(5, 1, 2, 3), nullptr);
}

// Growing the store moves no record: a vector copied them all into new memory at each growth
// (touching twice the memory and holding both copies meanwhile).
TEST(TriangleRecords, RecordsKeepTheirPlaceAsTheStoreGrows) {
  TriangleRecords records;
  records.reserve(3);
  std::vector<const TriangleRecord*> places;
  for (cet::TriangleId t = 0; t < 3; ++t) {
    records.at(t).v[0] = t;
    places.push_back(&records.at(t));
  }
  for (std::size_t size : {5000u, 100000u, 1000000u}) {
    records.reserve(size);
    for (cet::TriangleId t = 0; t < 3; ++t) {
      EXPECT_EQ(&records.at(t), places[t]) << "after growing to " << size;
      EXPECT_EQ(records.at(t).v[0], t);
    }
    EXPECT_EQ(records.at(static_cast<cet::TriangleId>(size - 1)).v[0], cet::kNoVertex) << "a new record is empty";
  }
}

// Every id keeps its own record across the blocks' boundaries (the first blocks ramp up in size),
// each at the place it got when first reserved.
TEST(TriangleRecords, EveryIdHasItsOwnRecordAcrossTheBlocks) {
  TriangleRecords records;
  constexpr cet::TriangleId kIds = 5000;
  std::vector<const TriangleRecord*> places;
  for (cet::TriangleId t = 0; t < kIds; ++t) {
    records.reserve(t + 1);
    records.at(t).v[0] = t;
    places.push_back(&records.at(t));
  }
  for (cet::TriangleId t = 0; t < kIds; ++t) {
    ASSERT_EQ(&records.at(t), places[t]) << "id " << t;
    ASSERT_EQ(records.at(t).v[0], t) << "id " << t;
    ASSERT_NE(records.find(t, t, cet::kNoVertex, cet::kNoVertex), nullptr) << "id " << t;
  }
}

// A face of a few triangles makes a small store: every record is written when its block is made,
// and a first block of 1024 records (56 KB) cost each small face 14 page faults.
TEST(TriangleRecords, ASmallFaceMakesASmallStore) {
  TriangleRecords records;
  records.reserve(10);
  EXPECT_LE(records.capacity(), 64u);
  records.reserve(100);
  EXPECT_LE(records.capacity(), 128u);
  records.reserve(1000);
  EXPECT_LE(records.capacity(), 1024u);
  records.reserve(100000);
  EXPECT_LE(records.capacity(), 100000u + 1024u);
  EXPECT_GE(records.capacity(), 100000u);
}

}  // namespace
}  // namespace cetview::brep
