// Requirement: glibc is asked for huge pages only where the kernel gives them on request, and a
// user's own glibc.malloc.hugetlb and other tunables are kept. Fails if the mode is misread (the
// unselected "madvise" of "[always] madvise never" counts) or if a tunable is lost or doubled.

#include <gtest/gtest.h>

#include "suites/huge_pages.hpp"

namespace cs::suites {
namespace {

TEST(HugePages, AskedForOnlyWhereTheKernelGivesThemOnRequest) {
  EXPECT_TRUE(huge_pages_on_request("always [madvise] never"));
  EXPECT_FALSE(huge_pages_on_request("[always] madvise never"));
  EXPECT_FALSE(huge_pages_on_request("always madvise [never]"));
  EXPECT_FALSE(huge_pages_on_request(""));  // unreadable: nobody has them
}

TEST(HugePages, TheTunableIsAddedToTheUsersOwn) {
  EXPECT_EQ(tunables_with_huge_pages(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=2"),
            "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
}

TEST(HugePages, AUsersOwnChoiceStands) {
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=0"), std::nullopt);
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=2"),
            std::nullopt);
  // A tunable whose name only begins like it is another one.
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlbx=0"),
            "glibc.malloc.hugetlbx=0:glibc.malloc.hugetlb=1");
}

}  // namespace
}  // namespace cs::suites
