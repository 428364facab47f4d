// orikin_bench: named benchmark scenarios; prints figures, asserts nothing about time.
#include <stdio.h>
int main(void)
{
    printf("no scenarios yet\n");
    return 0;
}
