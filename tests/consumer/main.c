/* The installed C API from C: a world, a carve, the state hash after a save and a load. */
#include <stdio.h>

#include <edgeland/edgeland.h>

int main(void) {
  const el_box box = {{0, 0}, {256, 256}};
  const el_point center = {128, 128};
  el_landscape* world = NULL;
  el_landscape* loaded = NULL;
  el_shape* blast = NULL;
  el_bytes* save = NULL;
  uint64_t a = 0, b = 1;
  size_t size = 0;
  const uint8_t* data;
  if (el_check_version(EL_VERSION) != EL_OK) return 1;
  if (el_landscape_create(&box, 1, NULL, &world, NULL) != EL_OK) return 1;
  if (el_shape_circle(&center, 40, &blast, NULL) != EL_OK) return 1;
  if (el_landscape_carve(world, blast, NULL, NULL) != EL_OK) return 1;
  if (el_landscape_save(world, &save, NULL) != EL_OK) return 1;
  data = el_bytes_data(save, &size);
  if (el_landscape_load(data, size, NULL, &loaded, NULL) != EL_OK) return 1;
  el_landscape_state_hash(world, &a, NULL);
  el_landscape_state_hash(loaded, &b, NULL);
  el_bytes_destroy(save);
  el_shape_destroy(blast);
  el_landscape_destroy(loaded);
  el_landscape_destroy(world);
  if (a != b) return 1;
  printf("consumer_c: ok\n");
  return 0;
}
