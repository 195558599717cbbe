#include "freespace/numbers/angle_polynomial.h"

namespace freespace {

template Interval threePatchDeterminant<Interval>(const PatchLine<Interval>&, const PatchLine<Interval>&,
                                                  const PatchLine<Interval>&, const Interval&, const Interval&);

}  // namespace freespace
