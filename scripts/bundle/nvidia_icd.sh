# nvidia_icd.sh - sourced by scripts/device-check.sh and the bundle's run.sh:
# nvidia_icd OUT_FOLDER finds NVIDIA's libnvidia-opencl.so.1 and, when no ICD
# file of the system names it, writes one (beside copies of the system's) to
# OUT_FOLDER/icd-vendors and exports OCL_ICD_VENDORS.  Prints what it did;
# returns 1 when an ICD file is needed and the driver is not installed.
nvidia_icd() {
  grep -qs nvidia /etc/OpenCL/vendors/*.icd 2>/dev/null && return 0
  [ -n "${OCL_ICD_VENDORS:-}" ] && return 0
  local library="" candidate vendors="$1/icd-vendors"
  for candidate in $(ldconfig -p 2>/dev/null | awk '/libnvidia-opencl\.so\.1/ {print $NF}') \
      /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1 /usr/lib64/libnvidia-opencl.so.1 \
      /usr/lib/libnvidia-opencl.so.1 /usr/local/nvidia/lib64/libnvidia-opencl.so.1; do
    [ -e "$candidate" ] && { library="$candidate"; break; }
  done
  [ -n "$library" ] || return 1
  mkdir -p "$vendors"
  cp /etc/OpenCL/vendors/*.icd "$vendors/" 2>/dev/null || true
  echo "$library" >"$vendors/nvidia.icd"
  export OCL_ICD_VENDORS="$vendors"
  echo "ICD: $vendors/nvidia.icd -> $library (OCL_ICD_VENDORS)"
}
