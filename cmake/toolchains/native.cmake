# The build machine itself (host-sim, vm-hil): no cross compiler.
