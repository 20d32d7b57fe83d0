// Catch2 entry point shared by the unit, gl and scenario suites.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
