#include <glint/material/normal_perturbation.h>

namespace glint {
namespace {

// Keeps the perturbed normal on the outside of the geometric surface: a shading normal
// behind the surface would make the frame send light through it.
void set_shading(SurfaceInteraction& si, const Vec3& n, const Vec3& tangent) {
    if (!(glm::dot(n, si.ng) > 0.0f) || !std::isfinite(n.x + n.y + n.z)) return;
    si.shading = Frame::from_normal_tangent(n, tangent);
}

}  // namespace

void NormalPerturbation::apply(SurfaceInteraction& si) const {
    if (m_is_normal_map)
        apply_normal_map(si);
    else
        apply_bump(si);
}

void NormalPerturbation::apply_bump(SurfaceInteraction& si) const {
    const Vec3 n = si.shading.n();
    // Step half a footprint in u and v, or a small fixed step without one.
    float du = 0.5f * (std::abs(si.dudx) + std::abs(si.dudy));
    float dv = 0.5f * (std::abs(si.dvdx) + std::abs(si.dvdy));
    if (!(du > 0.0f)) du = 5e-4f;
    if (!(dv > 0.0f)) dv = 5e-4f;
    const TextureContext here(si);
    TextureContext shifted_u = here, shifted_v = here;
    shifted_u.uv.x += du;
    shifted_u.p += du * si.dpdu;
    shifted_u.p_object += du * si.dpdu;
    shifted_v.uv.y += dv;
    shifted_v.p += dv * si.dpdv;
    shifted_v.p_object += dv * si.dpdv;
    const float height = m_texture->eval_float(here);
    const float dh_du = m_scale * (m_texture->eval_float(shifted_u) - height) / du;
    const float dh_dv = m_scale * (m_texture->eval_float(shifted_v) - height) / dv;
    // Tangents of the displaced surface p + scale h n (the normal's own change is ignored).
    const Vec3 dpdu = si.dpdu + dh_du * n;
    const Vec3 dpdv = si.dpdv + dh_dv * n;
    Vec3 bumped = glm::cross(dpdu, dpdv);
    const float length = glm::length(bumped);
    if (!(length > 0.0f)) return;
    bumped /= length;
    // uv may run either way round the normal; the bumped normal stays on n's side.
    if (glm::dot(glm::cross(si.dpdu, si.dpdv), n) < 0.0f) bumped = -bumped;
    si.dpdu = dpdu;
    si.dpdv = dpdv;
    set_shading(si, bumped, dpdu);
}

void NormalPerturbation::apply_normal_map(SurfaceInteraction& si) const {
    const Vec3 n = si.shading.n();
    const Rgb encoded = m_texture->eval(TextureContext(si));
    Vec3 local(2.0f * encoded.r - 1.0f, 2.0f * encoded.g - 1.0f, 2.0f * encoded.b - 1.0f);
    if (m_flip_y) local.y = -local.y;
    // Tangent along dp/du, bitangent towards growing v.
    const Frame frame = Frame::from_normal_tangent(n, si.dpdu);
    const Vec3 tangent = frame.s();
    Vec3 bitangent = frame.t();
    if (glm::dot(bitangent, si.dpdv) < 0.0f) bitangent = -bitangent;
    const Vec3 mapped = local.x * tangent + local.y * bitangent + local.z * n;
    const float length = glm::length(mapped);
    if (!(length > 0.0f)) return;
    set_shading(si, mapped / length, tangent);
}

}  // namespace glint
