#!/bin/sh
# Each batch kernel object (solver/src/batch_kernel.cpp compiled for one
# instruction set) may define global or weak code only inside its own
# namespace contact::batch_kernels::<name>. Prints the offenders, if any.
status=0
for object in "$@"; do
  name=$(printf '%s\n' "$object" | sed -E 's#.*/contact_batch_([A-Za-z0-9_]+)\.dir/.*#\1#')  # .../contact_batch_<name>.dir/...
  defined=$(nm -C --defined-only "$object" | awk '$2 ~ /^[TtWw]$/ && $2 ~ /[TW]/')
  count=$(printf '%s\n' "$defined" | grep -c "contact::batch_kernels::$name::")
  offenders=$(printf '%s\n' "$defined" | grep -v "contact::batch_kernels::$name::" | grep -v '^$')
  if [ -n "$offenders" ]; then
    echo "$object: code outside contact::batch_kernels::$name:"
    printf '%s\n' "$offenders" | head -20
    status=1
  elif [ "$count" -lt 3 ]; then
    echo "$object: expected the kernel's entry points, found $count symbols"
    status=1
  else
    echo "$object: $count global symbols, all in contact::batch_kernels::$name"
  fi
done
exit $status
