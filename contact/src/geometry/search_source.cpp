// The online 3D search as a contact geometry source.
//
// References: see search_source.hpp.
// Known deviations: see search_source.hpp.

#include "ferro/contact/geometry/search_source.hpp"

#include <stdexcept>

namespace ferro::contact {

WheelRailContact to_wheel_rail_contact(const ContactPoint& q) {
  WheelRailContact c = WheelRailContact::geometry_of(q);
  c.penetration = q.penetration;
  c.vertical_gap = q.vertical_gap;
  return c;
}

SearchContactSource::SearchContactSource(std::shared_ptr<const WheelRailPair> pair)
    : pair_(std::move(pair)) {
  if (!pair_) throw std::invalid_argument("SearchContactSource: the wheel-rail pair is null");
}

void SearchContactSource::contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                                   ContactScratch& /*scratch*/) const {
  out.clear();
  for (const ContactPoint& q : search_contacts(*pair_, pose)) {
    out.push_back(to_wheel_rail_contact(q));
  }
}

}  // namespace ferro::contact
