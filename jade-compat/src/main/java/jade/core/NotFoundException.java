package jade.core;

/** Something asked for by name or reference is not there (JADE's checked exception). */
public class NotFoundException extends Exception {
    private static final long serialVersionUID = 1L;

    public NotFoundException() {
    }

    public NotFoundException(String message) {
        super(message);
    }
}
