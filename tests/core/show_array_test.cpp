#include <ivis/core/errors.h>
#include <ivis/core/show_array.h>

#include <gtest/gtest.h>

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace ivis::core {
namespace {

/// A quad cell (file cell 0, two triangles) and a triangle cell (file cell 1), plus a cap vertex
/// 5 the file does not have:
///   3 ----- 2           triangles 0-1-2 and 0-2-3 from cell 0 (area 0.5 each)
///   |     / | \\         triangle 1-4-2 from cell 1 (area 0.5)
///   |   /   |   4       points: 0 (0,0) 1 (1,0) 2 (1,1) 3 (0,1) 4 (2,0.5) 5 cap
///   0 ----- 1
SurfaceField field()
{
    SurfaceField f;
    f.sourcePath = "f.vtp";
    f.mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5f, 0}, {0.5f, 0.5f, 1}};
    f.mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
    f.mesh.dataTriangleCount = 3;
    f.triangleCells = {0, 0, 1};
    f.arrays = {{"p", Association::Point, ValueType::Float32, 1, {0, 1, 2, 3, 4}},
                {"v", Association::Point, ValueType::Float64, 3, {3, 4, 0, 0, 0, 1, 1, 2, 2, 0, 0, 0, 6, 8, 0}},
                {"c", Association::Cell, ValueType::Int32, 1, {10, 40}},
                {"p", Association::Cell, ValueType::Int32, 1, {-1, -1}},
                {"a:b", Association::Cell, ValueType::Int32, 1, {7, 8}}};
    return f;
}

std::string errorOf(SurfaceField& f, const std::string& spec)
{
    try {
        showArray(f, spec, false);
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no error>";
}

// Each choice shows what it names, under the name it says, though "p" is both a point and a cell
// array and "a:b" holds the separator: the values checked against the arrays directly.
TEST(ShowArray, EachArrayChoiceShowsItsArrayOrComponent)
{
    const SurfaceField original = field();
    const std::vector<ArrayChoice> choices = arrayChoices(original);
    std::vector<std::string> names;
    for (const ArrayChoice& c : choices) names.push_back(c.name);
    EXPECT_EQ(names, (std::vector<std::string>{"p", "v magnitude", "v[0]", "v[1]", "v[2]", "c", "p", "a:b"}));
    const std::vector<int> arrayOf = {0, 1, 1, 1, 1, 2, 3, 4};
    const std::vector<int> componentOf = {0, kMagnitude, 0, 1, 2, 0, 0, 0};
    ASSERT_EQ(choices.size(), arrayOf.size());
    for (std::size_t i = 0; i < choices.size(); ++i) {
        SurfaceField f = field();
        showArray(f, choices[i].spec, false);
        const DataArray& array = original.arrays[std::size_t(arrayOf[i])];
        EXPECT_EQ(f.name, choices[i].name) << choices[i].spec;
        EXPECT_EQ(f.valuesOn, array.association) << choices[i].spec;
        EXPECT_EQ(choices[i].association, array.association) << choices[i].spec;
        if (array.association == Association::Point) {
            ASSERT_EQ(f.values.size(), 6u);
            for (std::size_t v = 0; v < 5; ++v)
                EXPECT_FLOAT_EQ(f.values[v], float(array.at(v, componentOf[i]))) << choices[i].spec << " vertex " << v;
        } else {
            ASSERT_EQ(f.values.size(), 3u);
            for (std::size_t t = 0; t < 3; ++t)
                EXPECT_FLOAT_EQ(f.values[t], float(array.at(original.triangleCells[t], componentOf[i])))
                    << choices[i].spec << " triangle " << t;
        }
    }
    EXPECT_TRUE(arrayChoices(SurfaceField{}).empty()) << "a generated surface has no arrays to choose";
}

// A choice whose spec would show another array, or be read as a pattern of names, is not offered.
TEST(ShowArray, ArrayChoicesLeaveOutSpecsThatNameSomethingElse)
{
    SurfaceField f = field();
    f.arrays.push_back({"v:0", Association::Point, ValueType::Float32, 1, {9, 9, 9, 9, 9}});
    f.arrays.push_back({"w*", Association::Point, ValueType::Float32, 1, {1, 1, 1, 1, 1}});
    std::vector<std::string> names;
    for (const ArrayChoice& c : arrayChoices(f)) {
        names.push_back(c.name);
        SurfaceField shown = f;
        showArray(shown, c.spec, false);
        EXPECT_EQ(shown.name, c.name) << c.spec;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"p", "v magnitude", "v[1]", "v[2]", "c", "p", "a:b", "v:0"}));
}

TEST(ShowArray, PointArrayPerVertexAndNanBeyondTheFile)
{
    SurfaceField f = field();
    showArray(f, "p", false);  // the point array wins over the cell array of the same name
    EXPECT_EQ(f.valuesOn, Association::Point);
    EXPECT_EQ(f.name, "p");
    ASSERT_EQ(f.values.size(), 6u);
    EXPECT_EQ(f.values[4], 4.0f);
    EXPECT_TRUE(std::isnan(f.values[5]));
}

TEST(ShowArray, ValuesBeyondFloatsAreRefusedNamingTheArray)
{
    // A Float64 value beyond the 32-bit floats the pictures colour became inf: one colour, legend 0.
    SurfaceField f = field();
    f.arrays[0].values[3] = -1e300;
    EXPECT_EQ(errorOf(f, "point:p"), "f.vtp: array 'p' holds -1e+300, beyond the 32-bit floats the pictures colour "
                                     "(3.4e+38): scale it");
    f.arrays[2].values[1] = 4e38;
    EXPECT_NE(errorOf(f, "c").find("array 'c' holds 4e+38"), std::string::npos);
    f.arrays[2].values[1] = 3e38;  // within: shown as it is
    EXPECT_EQ(errorOf(f, "c"), "<no error>");
}

TEST(ShowArray, VectorsByMagnitudeOrComponent)
{
    SurfaceField f = field();
    showArray(f, "v", false);
    EXPECT_EQ(f.name, "v magnitude");
    EXPECT_EQ(f.values[0], 5.0f);
    EXPECT_EQ(f.values[2], 3.0f);
    EXPECT_EQ(f.values[4], 10.0f);
    showArray(f, "v:magnitude", false);
    EXPECT_EQ(f.values[4], 10.0f);
    showArray(f, "v:1", false);
    EXPECT_EQ(f.name, "v[1]");
    EXPECT_EQ(f.values[0], 4.0f);
    EXPECT_EQ(f.values[4], 8.0f);
    EXPECT_NE(errorOf(f, "v:3").find("f.vtp: array 'v' has 3 components; '3' is not one of magnitude, 0..2"),
              std::string::npos);
    EXPECT_NE(errorOf(f, "v:x").find("'x' is not one of magnitude, 0..2"), std::string::npos);
}

TEST(ShowArray, CellArrayFlatPerTriangleOrAveragedOntoVertices)
{
    SurfaceField f = field();
    showArray(f, "c", false);
    EXPECT_EQ(f.valuesOn, Association::Cell);
    EXPECT_EQ(f.values, (std::vector<float>{10, 10, 40}));
    EXPECT_EQ(scalarAt(f, 2, glm::vec3(0.2f, 0.3f, 0.5f)), 40.0f);
    EXPECT_EQ(cornerScalars(f, 0), (std::array<float, 3>{10, 10, 10}));

    showArray(f, "c", true);
    EXPECT_EQ(f.valuesOn, Association::Point);
    EXPECT_EQ(f.name, "c (averaged)");
    ASSERT_EQ(f.values.size(), 6u);
    EXPECT_FLOAT_EQ(f.values[0], 10.0f);
    EXPECT_FLOAT_EQ(f.values[1], 25.0f);  // one triangle of each cell, equal areas
    EXPECT_FLOAT_EQ(f.values[2], 20.0f);  // two of cell 0, one of cell 1
    EXPECT_FLOAT_EQ(f.values[4], 40.0f);
    EXPECT_TRUE(std::isnan(f.values[5]));
}

TEST(ShowArray, NamesWithAColonAndUnknownNames)
{
    SurfaceField f = field();
    showArray(f, "a:b", false);
    EXPECT_EQ(f.values, (std::vector<float>{7, 7, 8}));
    EXPECT_EQ(errorOf(f, "wss"),
              "f.vtp: no array 'wss'; available: p (point), v (point, 3 components), c (cell), "
              "p (cell), a:b (cell) (of a point and a cell array of one name, cell:NAME chooses the cell array)");
    EXPECT_EQ(errorOf(f, "wss:1").rfind("f.vtp: no array 'wss:1'", 0), 0u);
}

TEST(ShowArray, DefaultIsTheFirstPointArrayElseTheFirstCellArray)
{
    SurfaceField f = field();
    std::rotate(f.arrays.begin(), f.arrays.begin() + 2, f.arrays.end());  // c, p (cell), a:b, p, v
    EXPECT_EQ(&defaultArray(f), &f.arrays[3]);
    f.arrays.resize(3);
    EXPECT_EQ(&defaultArray(f), &f.arrays[0]);
}

TEST(ShowArray, PointOrCellBeforeTheNameChoosesTheAssociation)
{
    // ParaView's Cell Data to Point Data, passing the cell data, leaves a point and a cell
    // "pressure": the cell one could not be chosen.
    SurfaceField f = field();  // p, v (point), c, p, a:b (cell)
    showArray(f, "cell:p", false);
    EXPECT_EQ(f.valuesOn, Association::Cell);
    EXPECT_EQ(f.values, (std::vector<float>{-1, -1, -1}));
    showArray(f, "point:p", false);
    EXPECT_EQ(f.valuesOn, Association::Point);
    showArray(f, "point:v:1", false);
    EXPECT_EQ(f.values[0], 4.0f);
    showArray(f, "cell:a:b", false);  // a cell array whose name holds a colon
    EXPECT_EQ(f.values, (std::vector<float>{7, 7, 8}));
    EXPECT_EQ(errorOf(f, "cell:v").rfind("f.vtp: no array 'cell:v'", 0), 0u);  // v is a point array
    EXPECT_NE(errorOf(f, "cell:v").find("cell:NAME chooses the cell array"), std::string::npos);
    EXPECT_EQ(qualifiedArrayName(f.arrays[3]), "cell:p");
    // A name that only looks prefixed: as it is, and split at its last ':' when no point "vel" is there.
    f.arrays.push_back({"point:vel", Association::Cell, ValueType::Float32, 3, {1, 2, 3, 4, 5, 6}});
    showArray(f, "point:vel:1", false);
    EXPECT_EQ(f.valuesOn, Association::Cell);
    EXPECT_EQ(f.values, (std::vector<float>{2, 2, 5}));
    showArray(f, "point:vel", false);
    EXPECT_EQ(f.name, "point:vel magnitude");
    f.arrays.pop_back();
    // The default array is shown by its qualified name: the cell p when it is the active scalars.
    f.arrays[3].activeScalars = true;
    showArray(f, qualifiedArrayName(defaultArray(f)), false);
    EXPECT_EQ(f.valuesOn, Association::Cell);
}

TEST(ShowArray, DefaultIsTheFilesActiveScalarsPointBeforeCell)
{
    // The VMTK files name ClippingArray their active scalars; their first point array is 0 everywhere.
    SurfaceField f = field();  // p, v (point), c, p, a:b (cell)
    f.arrays[2].activeScalars = true;
    EXPECT_EQ(&defaultArray(f), &f.arrays[2]);
    f.arrays[1].activeScalars = true;
    EXPECT_EQ(&defaultArray(f), &f.arrays[1]);
}

TEST(ShowArray, CellToPointTakesCellArraysOnly)
{
    SurfaceField f = field();  // p, v (point), c, p, a:b (cell)
    f.arrays[1].activeScalars = true;
    EXPECT_EQ(&defaultArray(f, true), &f.arrays[2]);  // the first cell array, not the active point v
    f.arrays[3].activeScalars = true;
    EXPECT_EQ(&defaultArray(f, true), &f.arrays[3]);  // the active cell scalars
    showArray(f, "c", true);
    EXPECT_EQ(f.valuesOn, Association::Point);
    EXPECT_EQ(f.name, "c (averaged)");
    try {
        showArray(f, "v", true);
        ADD_FAILURE() << "a point array is averaged from no cells";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "f.vtp: --cell-to-point averages a cell array; 'v' is a point array (a cell array "
                               "by name: --scalar cell:NAME)");
    }
    f.arrays.resize(2);
    EXPECT_THROW(defaultArray(f, true), InputError);
    f.arrays.clear();
    EXPECT_THROW(defaultArray(f, true), InputError);
}


TEST(ArrayPattern, StarAndQuestionMarkMakeAPattern)
{
    EXPECT_TRUE(isArrayPattern("pressure_t*"));
    EXPECT_TRUE(isArrayPattern("p?"));
    EXPECT_FALSE(isArrayPattern("pressure_t200"));
    EXPECT_FALSE(isArrayPattern("v:1"));
}

TEST(ArrayPattern, MatchesWholeNamesOnceInNaturalOrder)
{
    SurfaceField f = field();
    f.arrays.clear();
    for (const char* name : {"p_t1000", "p_t200", "q_t300", "p_t0400", "p_t30", "p_t200x", "p_t99"})
        f.arrays.push_back({name, Association::Point, ValueType::Float32, 1, {0, 0, 0, 0, 0}});
    f.arrays.push_back({"p_t200", Association::Cell, ValueType::Float32, 1, {0, 0}});  // a second p_t200: listed once
    EXPECT_EQ(arraysMatching(f, "p_t*"),
              (std::vector<std::string>{"p_t30", "p_t99", "p_t200", "p_t200x", "p_t0400", "p_t1000"}));
    EXPECT_EQ(arraysMatching(f, "?_t30?"), (std::vector<std::string>{"q_t300"}));
    EXPECT_EQ(arraysMatching(f, "*00"), (std::vector<std::string>{"p_t200", "p_t0400", "p_t1000", "q_t300"}));
}

TEST(ArrayPattern, BracketsAndBackslashesStandForThemselves)
{
    // CFD exports put units in brackets; fnmatch read "[Pa]" as one of 'P' or 'a'.
    SurfaceField f = field();
    f.arrays.clear();
    for (const char* name : {"WSS [Pa]_t2", "WSS [Pa]_t1", "WSS P_t1", "WSS a_t1", "a\\b_t1", "ab_t1"})
        f.arrays.push_back({name, Association::Point, ValueType::Float32, 1, {0, 0, 0, 0, 0}});
    EXPECT_EQ(arraysMatching(f, "WSS [Pa]_t*"), (std::vector<std::string>{"WSS [Pa]_t1", "WSS [Pa]_t2"}));
    EXPECT_EQ(arraysMatching(f, "a\\b_?1"), (std::vector<std::string>{"a\\b_t1"}));
}

TEST(ArrayPattern, WildcardsMatchAsFnmatchDoes)
{
    // Brute force: every pattern of up to 4 characters of "ab*?" against every name of up to 5 of
    // "ab", where fnmatch (no brackets, no backslashes) is the reference.
    auto words = [](const std::string& alphabet, std::size_t longest) {
        std::vector<std::string> all = {""};
        for (std::size_t k = 0; k < all.size(); ++k)
            if (all[k].size() < longest)
                for (char c : alphabet) all.push_back(all[k] + c);
        return all;
    };
    const std::vector<std::string> names = words("ab", 5);
    for (const std::string& pattern : words("ab*?", 4)) {
        SurfaceField f = field();
        f.arrays.clear();
        std::vector<std::string> expected;
        for (const std::string& name : names) {
            f.arrays.push_back({name, Association::Point, ValueType::Float32, 1, {0, 0, 0, 0, 0}});
            if (::fnmatch(pattern.c_str(), name.c_str(), 0) == 0) expected.push_back(name);
        }
        if (expected.empty()) {  // refused, naming the arrays
            EXPECT_THROW(arraysMatching(f, pattern), InputError) << pattern;
            continue;
        }
        std::vector<std::string> found = arraysMatching(f, pattern);
        std::sort(found.begin(), found.end());
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(found, expected) << pattern;
    }
}

TEST(ArrayPattern, NoMatchNamesTheArrays)
{
    const SurfaceField f = field();
    try {
        arraysMatching(f, "wss_*");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "f.vtp: no array matches 'wss_*'; available: p (point), v (point, 3 components), c (cell), "
                  "p (cell), a:b (cell) (of a point and a cell array of one name, cell:NAME chooses the cell array)");
    }
}

}  // namespace
}  // namespace ivis::core
