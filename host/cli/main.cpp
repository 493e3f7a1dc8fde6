#include <cstdio>
int main(int argc, char** argv) { (void)argc; (void)argv; std::puts("tessera: under construction"); return 0; }
