package jade.util.leap;

/** Adapts a Java iterator to JADE's {@link Iterator}. */
final class Iterators {
    private Iterators() {
    }

    @SuppressWarnings("rawtypes")
    static Iterator of(java.util.Iterator it) {
        return new Iterator() {
            @Override
            public boolean hasNext() {
                return it.hasNext();
            }

            @Override
            public Object next() {
                return it.next();
            }

            @Override
            public void remove() {
                it.remove();
            }
        };
    }
}
