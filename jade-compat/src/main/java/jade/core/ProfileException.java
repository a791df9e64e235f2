package jade.core;

/** A bad profile. */
public class ProfileException extends Exception {
    private static final long serialVersionUID = 1L;

    public ProfileException(String msg) {
        super(msg);
    }

    public ProfileException(String msg, Throwable cause) {
        super(msg, cause);
    }
}
