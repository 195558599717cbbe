#include "freespace/numbers/angle_polynomial.h"

namespace freespace {

template Interval threePatchDeterminant<Interval>(const PatchLine&, const PatchLine&, const PatchLine&,
                                                  const Interval&, const Interval&);

}  // namespace freespace
