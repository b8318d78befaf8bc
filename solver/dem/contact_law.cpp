// Contact-law family helpers (see contact_law.hpp).
#include "dem/contact_law.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace kolsky::dem {

namespace {
// The default-constructed alternative k of ContactLawParams (k < its size).
template <std::size_t... K>
ContactLawParams params_at(std::size_t k, std::index_sequence<K...>) {
  ContactLawParams out;
  (void)((k == K ? (out.emplace<K>(), true) : false) || ...);
  return out;
}
}  // namespace

ContactLawParams default_law_params(std::string_view name) {
  for (std::size_t k = 0; k < kContactLawNames.size(); ++k)
    if (kContactLawNames[k] == name)
      return params_at(k, std::make_index_sequence<std::variant_size_v<ContactLawParams>>{});
  throw std::out_of_range("unknown contact law '" + std::string(name) + "'");
}

}  // namespace kolsky::dem
