// The camera's primary ray through a pixel (core::CameraFrame).
uniform vec2 uViewport;         // width, height in pixels
uniform float uHalfHeight;      // tan(fov / 2), or the orthographic half height
uniform float uAspect;
uniform vec2 uWindowCentre;     // the image centre on the image plane (core::Camera::windowCentre)
uniform vec3 uEye;
uniform float uTargetDistance;  // from the eye to the camera's target
uniform vec3 uRight;
uniform vec3 uUp;
uniform vec3 uForward;
uniform bool uOrtho;

// core::CameraFrame::ray through @a pixel (pixel (0,0) is the top-left corner on the CPU).
void cameraRay(vec2 pixel, out vec3 origin, out vec3 direction)
{
    float sx = uWindowCentre.x + (2.0 * pixel.x / uViewport.x - 1.0) * uHalfHeight * uAspect;
    float sy = uWindowCentre.y + (1.0 - 2.0 * pixel.y / uViewport.y) * uHalfHeight;
    if (uOrtho) {
        origin = uEye + sx * uRight + sy * uUp;
        direction = uForward;
    } else {
        origin = uEye;
        direction = normalize(uForward + sx * uRight + sy * uUp);
    }
}
