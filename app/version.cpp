#include "version.h"

#include <OpenEXR/OpenEXRConfig.h>
#include <embree3/rtcore_config.h>
#include <openvdb/version.h>

namespace ivis::app {

std::string versionText(const std::string& program)
{
    return program + " " + IVIS_VERSION + " (OpenVDB " + OPENVDB_LIBRARY_VERSION_STRING + ", Embree " +
           RTC_VERSION_STRING + ", OpenEXR " + OPENEXR_VERSION_STRING + ")";
}

}  // namespace ivis::app
