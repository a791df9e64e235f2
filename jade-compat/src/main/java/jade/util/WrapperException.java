package jade.util;

/** JADE's base of exceptions that carry another one (a cause). */
public abstract class WrapperException extends Exception {
    private static final long serialVersionUID = 1L;

    protected WrapperException(String message, Throwable nested) {
        super(message, nested);
    }

    protected WrapperException(String message) {
        super(message);
    }

    /** The exception this one carries, or null. */
    public Throwable getNested() {
        return getCause();
    }
}
