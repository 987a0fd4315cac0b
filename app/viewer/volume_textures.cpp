#include "volume_textures.h"

#include <array>

namespace ivis::app {
namespace {

void uploadBox(const GlTexture& texture, GLint internal, GLenum format, GLenum type, const std::array<int, 3>& dims,
               const void* data, const char* what)
{
    glBindTexture(GL_TEXTURE_3D, texture.id());
    textureParameters(GL_TEXTURE_3D, GL_NEAREST);
    const bool empty = dims[0] * dims[1] * dims[2] == 0;
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glTexImage3D(GL_TEXTURE_3D, 0, internal, empty ? 1 : dims[0], empty ? 1 : dims[1], empty ? 1 : dims[2], 0, format,
                 type, empty ? static_cast<const void*>(none) : data);
    checkGl(what);
}

}  // namespace

VolumeTextures::VolumeTextures()
    : mFar(newName(glGenTextures)), mBand(newName(glGenTextures)), mTriangles(newName(glGenTextures))
{
}

void VolumeTextures::upload(const DenseSlices& slices)
{
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    uploadBox(mFar, GL_RGBA32F, GL_RGBA, GL_FLOAT, slices.far.dims, slices.far.values.data(),
              "uploading the far-field texture");
    uploadBox(mBand, GL_RGBA32F, GL_RGBA, GL_FLOAT, slices.band.dims, slices.band.values.data(),
              "uploading the band texture");
    uploadBox(mTriangles, GL_R32I, GL_RED_INTEGER, GL_INT, slices.triangles.dims, slices.triangles.values.data(),
              "uploading the triangle texture");
    glBindTexture(GL_TEXTURE_3D, 0);
}

void VolumeTextures::bind() const
{
    glActiveTexture(GL_TEXTURE0 + kFarUnit);
    glBindTexture(GL_TEXTURE_3D, mFar.id());
    glActiveTexture(GL_TEXTURE0 + kBandUnit);
    glBindTexture(GL_TEXTURE_3D, mBand.id());
    glActiveTexture(GL_TEXTURE0 + kTriangleUnit);
    glBindTexture(GL_TEXTURE_3D, mTriangles.id());
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace ivis::app
