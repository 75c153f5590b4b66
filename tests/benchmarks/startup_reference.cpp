// The floor of a railjoint process's start-up: a program that does nothing
// but is linked to Bullet (double) and toml++, the two libraries every
// simulating command needs. startup_time.cpp times railjoint against it.
// The calls below never run; they keep both libraries linked and loaded.

#include <btBulletCollisionCommon.h>
#include <toml++/toml.h>

int main(int argc, char** argv) {
  if (argc > 1000) {
    btDefaultCollisionConfiguration configuration;
    return static_cast<int>(toml::parse(argv[0]).size()) + (configuration.getPersistentManifoldPool() != nullptr);
  }
  return 0;
}
