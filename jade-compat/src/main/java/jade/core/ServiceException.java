package jade.core;

/** JADE's exception of a platform service; concord-jade throws it where a JADE service is not there. */
public class ServiceException extends jade.util.WrapperException {
    private static final long serialVersionUID = 1L;

    public ServiceException() {
        this("");
    }

    public ServiceException(String message) {
        super(message);
    }

    public ServiceException(String message, Throwable nested) {
        super(message, nested);
    }
}
