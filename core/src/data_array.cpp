#include <ivis/core/data_array.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::core {

double DataArray::at(std::size_t tuple, int component) const
{
    const double* t = values.data() + tuple * std::size_t(components);
    if (component != kMagnitude) return t[component];
    double sum = 0.0;
    for (int c = 0; c < components; ++c) sum += t[c] * t[c];
    return std::sqrt(sum);
}

const char* associationName(Association association)
{
    return association == Association::Point ? "point" : "cell";
}

const char* valueTypeName(ValueType type)
{
    static const char* const kNames[] = {"Int8",   "UInt8", "Int16",  "UInt16",  "Int32",
                                         "UInt32", "Int64", "UInt64", "Float32", "Float64"};
    return kNames[int(type)];
}

std::size_t valueTypeSize(ValueType type)
{
    static const std::size_t kSizes[] = {1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
    return kSizes[int(type)];
}

std::pair<double, double> finiteRange(const DataArray& array, int component, const std::vector<char>& keep)
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (std::size_t t = 0; t < array.tuples(); ++t) {
        if (!keep.empty() && (t >= keep.size() || !keep[t])) continue;
        const double v = array.at(t, component);
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (lo > hi) return {std::nan(""), std::nan("")};
    return {lo, hi};
}

}  // namespace ivis::core
