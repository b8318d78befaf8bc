// The text's SHPB geometry (Sec. 2.2, Song et al. 2009 and Martin et al. 2009; the same set-up
// in Secs. 3.2 and 4.2): the sand specimen, and the bars whose faces it sits between. Every
// default specimen and bar size in the solver starts from these; the reproduction sets' scene
// files write their own sizes.
#pragma once

namespace kolsky {

/// L_s, the specimen length (m): "a length of 9.3 mm" (Sec. 2.2).
inline constexpr double kSpecimenLength = 0.0093;
/// The specimen diameter (m): "a diameter of 19.1 mm" (Sec. 2.2); the inner radius of the
/// confining tube is kSpecimenDiameter / 2.
inline constexpr double kSpecimenDiameter = 0.0191;
/// The diameter of the incident and transmission bars (m): "the same diameter of 19.1 mm"
/// (Sec. 2.2); equal to the specimen's, but a different quantity.
inline constexpr double kBarDiameter = 0.0191;

}  // namespace kolsky
