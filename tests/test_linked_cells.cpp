// The linked-cell search finds every close pair that the all-pairs search finds.
#include "harness/granular/linked_cells.hpp"
#include "harness/granular/random_stream.hpp"

#include <catch2/catch.hpp>
#include <set>
#include <utility>

using namespace rotbench;

namespace {

std::set<std::pair<std::size_t, std::size_t>> close_pairs_by_cells(const std::vector<Vec3>& points, double reach) {
    LinkedCells cells;
    cells.build(points, reach);
    std::set<std::pair<std::size_t, std::size_t>> found;
    std::size_t visits = 0;
    cells.for_each_pair([&](std::size_t i, std::size_t j) {
        ++visits;
        CHECK(i != j);
        const auto pair = std::minmax(i, j);
        CHECK(!found.count(pair));  // at most one visit
        if ((points[i] - points[j]).norm() < reach) found.insert(pair);
    });
    return found;
}

std::set<std::pair<std::size_t, std::size_t>> close_pairs_by_all(const std::vector<Vec3>& points, double reach) {
    std::set<std::pair<std::size_t, std::size_t>> found;
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
            if ((points[i] - points[j]).norm() < reach) found.insert({i, j});
    return found;
}

}  // namespace

TEST_CASE("linked cells: the same close pairs as the all-pairs search") {
    RandomStream random(7);
    std::vector<Vec3> points;
    for (int i = 0; i < 2000; ++i) points.emplace_back(random.uniform(-0.3, 0.5), random.uniform(0.0, 0.2), random.uniform(-1.0, 0.0));
    const double reach = 0.03;
    const auto expected = close_pairs_by_all(points, reach);
    REQUIRE(expected.size() > 500);  // the test sees many pairs
    CHECK(close_pairs_by_cells(points, reach) == expected);

    SECTION("a point far away makes the cells larger, not more numerous, and loses no pair") {
        points.emplace_back(1e6, 0.0, 0.0);
        CHECK(close_pairs_by_cells(points, reach) == expected);
    }
    SECTION("points on the cells' boundaries and repeated points") {
        for (int i = 0; i < 50; ++i) points.push_back(Vec3(i * reach, 0.0, 0.0));
        points.push_back(points[3]);
        CHECK(close_pairs_by_cells(points, reach) == close_pairs_by_all(points, reach));
    }
}

TEST_CASE("linked cells: bad input is refused") {
    LinkedCells cells;
    CHECK_THROWS(cells.build({Vec3(0.0, 0.0, 0.0)}, 0.0));
    CHECK_THROWS(cells.build({Vec3(NAN, 0.0, 0.0)}, 1.0));
    CHECK_NOTHROW(cells.build({}, 1.0));
}
