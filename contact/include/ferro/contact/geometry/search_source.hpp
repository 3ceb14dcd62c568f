#pragma once
// The online 3D contact search of wheel_rail_geometry.hpp as a contact geometry source.
//
// References: see wheel_rail_geometry.hpp (search).
// Known deviations: allocates (the search builds its candidate lists), about 0.1 ms per call;
// use the tables in long runs.

#include <memory>
#include <string_view>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::contact {

/// WheelRailContact of a search point (profile coordinates and gap carried over).
[[nodiscard]] WheelRailContact to_wheel_rail_contact(const ContactPoint& point);

/// Online 3D search: every penetrating point of both wheels (one per connected run of
/// interpenetration, tread and flange), exactly as search_contacts(). Allocates per call.
class SearchContactSource final : public ContactGeometrySource {
 public:
  explicit SearchContactSource(std::shared_ptr<const WheelRailPair> pair);
  [[nodiscard]] std::string_view name() const override { return "search"; }
  using ContactGeometrySource::contacts;
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                ContactScratch& scratch) const override;
  [[nodiscard]] const WheelRailPair& pair() const { return *pair_; }
  [[nodiscard]] const WheelRailPair* profile_pair() const override { return pair_.get(); }

 private:
  std::shared_ptr<const WheelRailPair> pair_;
};

}  // namespace ferro::contact
