#include <gtest/gtest.h>
TEST(BumpLimits, Placeholder) {}
